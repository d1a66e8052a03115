"""Tools for whoever writes a lab: `assign` writes each starter from its solution, `lint-lab` states the rules a
lab keeps (lab_rules.py, one function each), `new-lab` writes a new lab from one template (lab_template.py)."""
