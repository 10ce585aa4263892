"""Lubricant properties, air properties, film thickness and lubrication regime."""
