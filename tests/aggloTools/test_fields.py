"""aggloTools.fields: plane means of a channel folded about its centre
plane, by hand values."""

import numpy as np

from aggloTools import fields


def test_folded():
    y = np.array([0.5, 1.5, 2.5, 3.5] * 2)
    q = np.array([1.0, 2.0, 4.0, 8.0, 3.0, 4.0, 6.0, 10.0])
    # plane means 2, 3, 5, 9; folded (2 + 9)/2, (3 + 5)/2
    assert fields.plane_means(y, q).tolist() == [2, 3, 5, 9]
    assert fields.plane_means(y, q, per_cell=True).tolist() == \
        [2, 3, 5, 9] * 2
    assert fields.folded(y, q).tolist() == [5.5, 4.0]
    assert fields.folded(y, q, odd=True).tolist() == [-3.5, -1.0]
