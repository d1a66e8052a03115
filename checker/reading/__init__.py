"""Reading a submission's source as Python does: its text and lines, the handout outside the step regions,
and the rules for the code inside them; nothing here runs the student's code."""
