"""Shared test set-up: any test that opens a window uses SDL's dummy drivers."""
import os

os.environ.setdefault("SDL_VIDEODRIVER", "dummy")
os.environ.setdefault("SDL_AUDIODRIVER", "dummy")
os.environ.setdefault("PYGAME_HIDE_SUPPORT_PROMPT", "1")


def pytest_configure(config):
    """Register the `slow` marker: long stability runs (CI runs them; `-m "not slow"` skips them locally)."""
    config.addinivalue_line("markers", "slow: long-running stability case (tens of seconds); CI still runs it")
