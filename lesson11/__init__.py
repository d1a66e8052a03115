"""Lesson 11, SAT & Rotational Collisions: the lesson material and the physics2d package."""
import os

os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")  # keep students' output to their own lines
