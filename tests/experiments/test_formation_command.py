"""``soccer-sim formation show --out``: a file name gets ``.png`` added, a directory gets a
``.png`` file inside it, and the command says which file it wrote."""

from __future__ import annotations

from experiments.cli import main


def test_formation_show_says_the_file_it_wrote(tmp_path, capsys) -> None:
    assert main(["formation", "show", "4-3-3", "--out", str(tmp_path / "picture")]) == 0
    assert f"wrote {tmp_path / 'picture.png'}" in capsys.readouterr().out
    assert (tmp_path / "picture.png").is_file() and not (tmp_path / "picture").exists()
    folder = tmp_path / "figures"
    folder.mkdir()
    assert main(["formation", "show", "4-3-3", "--out", str(folder)]) == 0
    written = capsys.readouterr().out.split("wrote ", 1)[1].split()[0]
    assert written.startswith(str(folder) + "/") and written.endswith(".png")
    assert (folder / written.rsplit("/", 1)[1]).is_file()
