"""Writing results: the readable report, --json, Gradescope's results.json, CSV and the HTML page,
and where output files may go without writing over anything the user did not ask for."""
