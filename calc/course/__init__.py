"""The course around the workbook: what a lecturer hands out and grades.

* :mod:`.variants`: each student's own brief, a seeded variant of the indexing table's axis
  (table inertia, index, move and dwell), as the brief's Markdown and as the case file the
  lecturer grades against;
* :mod:`.checkpoint`: the graded checkpoint's items, the package's values for a variant and a
  submission graded against them within each item's tolerance (the autograder's checks);
* :mod:`.selfcheck`: a notebook's self-check read from its Markdown (options, key, numerical
  item) and scored;
* :mod:`.material`: what students receive and what the lecturer keeps (``make student``,
  ``make lecturer``).

The course is an output of the package: it reads cases and evaluates them, nothing below imports it.
"""
