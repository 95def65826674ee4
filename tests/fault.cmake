# fault tests: filled in by the reliability work (issue 8).
