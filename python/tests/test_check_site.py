"""`make site`'s check of the built site (docs/_ext/check_site.py; issue 23, item 2): ready for
any static host. A small site written here holds one of each kind of address the check must
pass and, one at a time, each kind it must refuse (negative controls: a CDN script, as
sphinx-gallery's execution-times page loads; a CSS font from the network; a root-absolute
link; a missing file; the lab's server address)."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "docs" / "_ext"))

import check_site  # noqa: E402

GOOD_PAGE = """<!doctype html><html><head>
<link rel="stylesheet" href="_static/site.css?digest=1">
<link rel="icon" href="data:,">
<link rel="canonical" href="https://example.org/poinsot/">
<script src="_static/app.js"></script>
<style>.x { background: url(data:image/png;base64,AAAA) }</style>
</head><body>
<a href="sub/page.html#part">inside</a> <a href="sub/">a folder</a> <a href="#top">here</a>
<a href="https://github.com/">out: a link the reader may follow</a> <a href="mailto:x@y.z">mail</a>
<img src="_static/pic.png" srcset="_static/pic.png 1x, _static/pic.png 2x">
<p>The lab's server binds to 127.0.0.1 only (prose, not an address).</p>
</body></html>
"""


@pytest.fixture()
def site(tmp_path: Path) -> Path:
    root = tmp_path / "html"
    (root / "_static").mkdir(parents=True)
    (root / "sub").mkdir()
    (root / "index.html").write_text(GOOD_PAGE)
    (root / "sub" / "page.html").write_text('<a href="../index.html">up</a>')
    (root / "sub" / "index.html").write_text("<p>folder</p>")
    (root / "_static" / "site.css").write_text(
        "@font-face { src: url('fonts/a.woff2') } .y { background: url(pic.png) }"
    )
    (root / "_static" / "fonts").mkdir()
    (root / "_static" / "fonts" / "a.woff2").write_bytes(b"w")
    (root / "_static" / "pic.png").write_bytes(b"p")
    (root / "_static" / "app.js").write_text("const where = location.origin;\n")
    # a theme template among the static files is no page
    (root / "_static" / "macros.html").write_text("<script src=\"{{ pathto('x.js') }}\"></script>")
    return root


def test_a_site_of_relative_addresses_inside_it_passes(site: Path) -> None:
    problems, pages = check_site.check_site(site)
    assert problems == []
    assert pages == 3
    assert check_site.main([str(site)]) == 0


@pytest.mark.parametrize(
    ("file", "text", "expected"),
    [
        (
            "sg_execution_times.html",
            '<script src="https://cdn.datatables.net/2.0/datatables.min.js"></script>',
            "loaded from the network",
        ),
        ("a.html", '<link rel="stylesheet" href="//cdn.example.org/x.css">', "network"),
        ("_static/f.css", "@import 'https://fonts.example.org/css';", "network"),
        ("_static/g.css", ".z { background: url(https://example.org/i.png) }", "network"),
        ("b.html", '<a href="/api.html">API</a>', "root-absolute"),
        ("c.html", '<img src="_static/missing.png">', "no such file"),
        ("d.html", '<a href="../../etc/passwd">x</a>', "leaves the site"),
        ("e.html", '<a href="http://127.0.0.1:8123/?scene=top">lab</a>', "loopback"),
        ("lab/x.js", "const share = 'http://localhost:8000/';", "loopback"),
    ],
)
def test_each_kind_of_address_a_static_host_cannot_serve_is_refused(
    site: Path, file: str, text: str, expected: str, capsys: pytest.CaptureFixture[str]
) -> None:
    target = site / file
    target.parent.mkdir(parents=True, exist_ok=True)
    target.write_text(text)
    problems, _ = check_site.check_site(site)
    assert len(problems) == 1 and expected in problems[0] and file in problems[0], problems
    assert check_site.main([str(site)]) == 1
    assert expected in capsys.readouterr().err


def test_no_site_is_a_problem(tmp_path: Path) -> None:
    problems, pages = check_site.check_site(tmp_path)
    assert pages == 0 and "no index.html" in problems[0]
