"""Tools for whoever writes a lab: `assign` writes each lab's starter from its solution."""
