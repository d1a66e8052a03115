"""The checker packaged for autograding platforms (Gradescope, GitHub Classroom, PrairieLearn): the
`package` command and the scripts it ships in templates/."""
