"""The Billiards lab: checks.py (its checks), probes.py (its probes), scenes.py (its scenes)."""
