"""Where the project is: the folder holding checker/, lesson11/, starters/ and solutions/ (below every other module)."""
import os

PROJECT_ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
