# End-to-end CLI cases: one CTest per (input file, switch string).
