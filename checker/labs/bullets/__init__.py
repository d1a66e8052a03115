"""The Bullets lab: checks.py (its checks), probes.py (its probes' inputs and references), scenes.py (its scene)."""
