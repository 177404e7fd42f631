# SPDX-License-Identifier: GPL-3.0-or-later
"""NumPy .npy height maps as numpy.save writes them: read_areal and the CLI's --areal give the
array's heights (array[iy, ix] = z(ix, iy)), in every dtype and order numpy writes for floats,
and the same numbers as the text matrix of the same heights."""
import numpy as np
import pytest

import roughcontact as rc


@pytest.fixture
def heights():
    rng = np.random.default_rng(7)
    return rng.normal(scale=0.5e-6, size=(12, 16))  # ny = 12 rows along y, nx = 16 along x


@pytest.mark.parametrize("convert", [
    lambda a: a,                                  # '<f8', C order
    lambda a: np.asfortranarray(a),               # Fortran order
    lambda a: a.astype(">f8"),                    # big-endian
    lambda a: a.astype("<f4"),                    # float32
    lambda a: np.asfortranarray(a.astype(">f4")),
])
def test_read_areal_gives_the_arrays_heights(tmp_path, heights, convert):
    a = convert(heights)
    path = tmp_path / "map.npy"
    np.save(path, a)
    s = rc.read_areal(str(path), dx=2e-6, dy=3e-6)
    assert (s.nx, s.ny) == (16, 12)
    assert (s.dx, s.dy) == (2e-6, 3e-6)
    # float32 is exact in float64: the values numpy holds, bit for bit.
    np.testing.assert_array_equal(np.asarray(s.heights), np.asarray(a, dtype=np.float64))


def test_cli_reads_npy_as_the_text_matrix(tmp_path, heights, cli):
    np.save(tmp_path / "map.npy", heights)
    np.savetxt(tmp_path / "map.txt", heights, fmt="%.17g")
    args = ["--model", "hertz", "--E", "200e9", "--nu", "0.3", "--dx", "2e-6", "--loads", "1e-4,1e-3"]
    from_npy = cli("--areal", tmp_path / "map.npy", *args)
    from_txt = cli("--areal", tmp_path / "map.txt", *args)
    assert from_npy.status == 0, from_npy.err
    assert from_npy.out == from_txt.out


def test_not_a_height_array_is_named(tmp_path):
    path = tmp_path / "ints.npy"
    np.save(path, np.zeros((12, 16), dtype=np.int64))
    with pytest.raises(rc.InputError, match="dtype is '<i8'"):
        rc.read_areal(str(path), dx=1e-6)
