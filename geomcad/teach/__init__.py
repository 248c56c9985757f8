"""For teachers: variants with answer keys and task cards, class grading, batch builds.

- :mod:`~geomcad.teach.variants`: ``geomcad variants TEMPLATE``: reproducible variants of a
  problem id or a file, each solved before it is kept, with the rejected ones counted by reason;
- :mod:`~geomcad.teach.keys`: which results go into the answer key and how they are printed;
- :mod:`~geomcad.teach.transmission`: the transmission angle of a linkage file over a full turn;
- :mod:`~geomcad.teach.roster`: a class roster, who gets which variant (``--students``);
- :mod:`~geomcad.teach.cards`: the A4 task card of a variant and the answer-key sheet;
- :mod:`~geomcad.teach.quantities`: a card's given data and what to find, in the subject's
  notation;
- :mod:`~geomcad.teach.tables`: the one CSV reader (any encoding and separator) and the XLSX
  writer (answers.xlsx, the register);
- :mod:`~geomcad.teach.batch`: ``geomcad verify --batch``, a class graded from a CSV, with
  tolerances and the register;
- :mod:`~geomcad.teach.jobs`: process pools with a progress bar (``build --jobs``).

This package sits on top of the library (with ``problem``, ``documents`` and ``verify``).
"""

#: Default lower limit of a linkage file's transmission angle in ``geomcad variants`` (degrees).
MIN_TRANSMISSION_DEG = 40.0
