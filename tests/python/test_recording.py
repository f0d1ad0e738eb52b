"""Recordings as NumPy structured arrays: a field per CSV column with the column's name,
the very numbers of the file, and bad files as MhdError at file:line."""

import os

import numpy as np
import pytest

import mhd
from conftest import repo_path

RECORDING = repo_path("tests", "data", "server", "recording_head.csv")


def test_fields_are_the_csv_columns_in_order():
    with open(RECORDING) as f:
        header = f.readline().strip().split(",")
    assert mhd.recording_columns().split(",") == header
    assert list(mhd.recording_dtype().names) == header


def test_the_array_holds_the_files_numbers():
    rec = mhd.read_recording(RECORDING)
    text = np.genfromtxt(RECORDING, delimiter=",", names=True)
    assert rec.shape == text.shape and len(rec) > 3
    for name in text.dtype.names:
        np.testing.assert_array_equal(rec[name], text[name], err_msg=name)
    assert rec.dtype["t_s"] == np.float64
    assert rec.dtype["contact"] == np.uint8 and rec.dtype["contact_object"] == np.int32
    assert not any(rec.dtype[name].hasobject for name in rec.dtype.names)


def test_a_bad_number_is_an_mhd_error_at_its_line(tmp_path):
    with open(RECORDING) as f:
        lines = f.readlines()
    cells = lines[2].split(",")
    cells[7] = "abc"  # hip_z_m
    lines[2] = ",".join(cells)
    bad = tmp_path / "bad.csv"
    bad.write_text("".join(lines))
    with pytest.raises(mhd.MhdError, match=rf"^{bad}:3: error: .*hip_z_m") as caught:
        mhd.read_recording(bad)
    assert caught.value.diagnostics[0].line == 3


def test_a_missing_file_is_an_mhd_error(tmp_path):
    with pytest.raises(mhd.MhdError, match=rf"{tmp_path}/none\.csv"):
        mhd.read_recording(tmp_path / "none.csv")


def test_a_device_or_a_fifo_is_refused_unread(tmp_path):
    # /dev/zero would grow without end and a FIFO block for ever: the CLI's bounds.
    fifo = tmp_path / "pipe.csv"
    os.mkfifo(fifo)
    for path in ("/dev/zero", str(fifo)):
        with pytest.raises(mhd.MhdError, match="not a regular file"):
            mhd.read_recording(path)
