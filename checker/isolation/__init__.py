"""Running a student's file alone: the child process and its limits, the warm zygote it is forked from,
the run's own user and jail, its disk quota (disk.py), and the clean-up that leaves nothing of one run to the next."""
