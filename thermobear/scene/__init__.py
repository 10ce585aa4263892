"""Scene files: what a user describes, validated and converted to SI once."""
from thermobear.scene.scene import Scene, load_scene, scene_from_dict, SUPPLIES  # noqa: F401
