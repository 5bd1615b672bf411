"""formations.input_files: a reader opens only a regular file (or a directory where one is
expected), of at most the format's size, without ever blocking on a FIFO."""

from __future__ import annotations

import errno

import pytest

import formations
from formations.files import FORMATION_FILE_LIMIT
from formations.input_files import check_input, open_input, read_input
from tests.experiments.special_files import device_node, fifo
from soccer_sim.config import STANDARD_FIELD as FIELD


def test_a_regular_file_is_read(tmp_path) -> None:
    path = tmp_path / "a.txt"
    path.write_bytes(b"hello")
    assert read_input(path, limit=5) == b"hello"
    assert check_input(path).st_size == 5


def test_a_fifo_is_refused_without_waiting_for_a_writer(tmp_path) -> None:
    path = fifo(tmp_path)
    with pytest.raises(OSError, match=r"not a regular file \(a FIFO\)") as caught:
        open_input(path)
    assert caught.value.filename == str(path) and caught.value.errno == errno.EINVAL
    with pytest.raises(OSError, match="a FIFO"):
        check_input(path)


@pytest.mark.parametrize("kind", ["zero", "urandom", "null"])
def test_a_device_is_refused_even_through_a_link(tmp_path, kind) -> None:
    link = tmp_path / "link"
    link.symlink_to(device_node(tmp_path, kind))
    with pytest.raises(OSError, match=r"not a regular file \(a character device\)"):
        read_input(link, limit=10)


def test_a_directory_is_refused_unless_expected(tmp_path) -> None:
    with pytest.raises(OSError, match=r"a directory") as caught:
        check_input(tmp_path)
    assert caught.value.errno == errno.EISDIR
    assert check_input(tmp_path, directory=True)


def test_a_file_over_its_limit_is_refused(tmp_path) -> None:
    path = tmp_path / "big.conf"
    with open(path, "wb") as handle:
        handle.truncate(FORMATION_FILE_LIMIT + 1)
    with pytest.raises(OSError, match="larger than the 16 MiB a formation file may hold") as caught:
        formations.load(path, field=FIELD)
    assert caught.value.errno == errno.EFBIG


def test_formation_readers_refuse_special_files(tmp_path) -> None:
    path = fifo(tmp_path, "normal-formation.conf")
    for load in (formations.load, formations.read_any, formations.load_helios):
        with pytest.raises(OSError, match="not a regular file"):
            load(path, field=FIELD)
