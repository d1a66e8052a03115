"""Showing what happened: the --show window (a recorded scene beside the lesson's, failing cases drawn)
and the --pictures filmstrips, with the scene run for a failed function check."""
