"""Report indices: the default target's figure pages and the validation target's pages, each linked once."""

from pathlib import Path

import pytest

from vibroadhesion.report import PAGES, VALIDATION_PAGES, write_index


@pytest.mark.parametrize(("name", "pages", "other"), [("index", PAGES, VALIDATION_PAGES),
                                                      ("validation_index", VALIDATION_PAGES, PAGES)])
def test_index_links_its_own_pages_only(tmp_path: Path, name, pages, other) -> None:
    out = tmp_path / f"{name}.html"
    write_index(out)
    text = out.read_text()
    for stem, _ in pages:
        assert text.count(f'<li><a href="{stem}.html">') == 1
    for stem, _ in other:
        assert f'<li><a href="{stem}.html">' not in text


def test_unknown_index_name_is_an_error(tmp_path: Path) -> None:
    with pytest.raises(ValueError, match="unknown index"):
        write_index(tmp_path / "other.html")
    assert list(tmp_path.iterdir()) == []
