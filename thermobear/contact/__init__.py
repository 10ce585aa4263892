"""Bearing geometry, materials, Hertz point contact and ball kinematics."""
