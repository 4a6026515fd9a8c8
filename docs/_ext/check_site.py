"""Checks that a built site is ready for any static host (``make site``; issue 23, item 2).

    python docs/_ext/check_site.py docs/_build/html

Reads every HTML and CSS file of the site and refuses (exit status 1, one line per problem):

* anything a page or a stylesheet would load from the network: a ``<script src>``, ``<link
  href>``, ``<img src>``/``srcset``, ``<iframe>``, ``<video>``/``<audio>``/``<source>``,
  ``<object data>``, ``<embed>`` or CSS ``url()``/``@import`` whose address has a scheme other
  than ``data:``/``blob:`` or starts with ``//`` (links a reader may follow, ``<a href>``, may
  leave the site);
* a root-absolute address (``/x``, for a link too): it breaks on a host that serves the site
  from a sub-folder, as GitHub Pages serves a project's site;
* a loaded file or a link inside the site that is not there;
* an address on ``127.0.0.1``, ``localhost`` or ``[::1]`` in any page, stylesheet or script: a
  developer's machine (``poinsot lab``'s server), dead on any other.

Pages are the HTML files outside ``_static/`` (whose HTML files are the theme's templates, not
pages). Nothing is fetched; the whole site is read from disk (10-15 s on two busy cores).
"""

from __future__ import annotations

import re
import sys
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import unquote, urlsplit

#: (tag, attribute) pairs whose address the browser loads with the page.
LOADED = {
    ("script", "src"),
    ("link", "href"),
    ("img", "src"),
    ("iframe", "src"),
    ("video", "src"),
    ("video", "poster"),
    ("audio", "src"),
    ("source", "src"),
    ("track", "src"),
    ("object", "data"),
    ("embed", "src"),
    ("input", "src"),
}

#: <link rel=...> values that are not requests made by the page (a link to another document).
NOT_LOADED_LINK_RELS = {
    "canonical",
    "alternate",
    "prev",
    "next",
    "index",
    "search",
    "author",
    "help",
}

#: Schemes of addresses that load nothing from anywhere.
LOCAL_SCHEMES = {"data", "blob", "about", "javascript"}

#: An address on a developer's own machine.
LOOPBACK = re.compile(r"\b(?:https?|wss?)://(?:127\.0\.0\.1|localhost|\[::1\])", re.IGNORECASE)

_CSS_URL = re.compile(r"""url\(\s*(['"]?)([^'")]*)\1\s*\)|@import\s+(['"])([^'"]+)\3""")


class _Refs(HTMLParser):
    """The addresses of one page: (what, address, loaded) for each reference."""

    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.refs: list[tuple[str, str, bool]] = []
        self._style = False
        self.styles: list[str] = []

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        a = {k: v for k, v in attrs if v is not None}
        if tag == "style":
            self._style = True
        for key, value in a.items():
            if key == "style":
                self.styles.append(value)
            if (tag, key) in LOADED:
                rels = set(a.get("rel", "").lower().split())
                loaded = not (tag == "link" and rels and rels <= NOT_LOADED_LINK_RELS)
                self.refs.append((f"<{tag} {key}>", value, loaded))
            elif key == "srcset" and tag in ("img", "source"):
                for part in value.split(","):
                    if part.strip():
                        self.refs.append((f"<{tag} srcset>", part.split()[0], True))
            elif tag == "a" and key == "href":
                self.refs.append(("<a href>", value, False))

    def handle_endtag(self, tag: str) -> None:
        if tag == "style":
            self._style = False

    def handle_data(self, data: str) -> None:
        if self._style:
            self.styles.append(data)


def _css_refs(text: str) -> list[str]:
    return [m.group(2) if m.group(2) is not None else m.group(4) for m in _CSS_URL.finditer(text)]


def _check_ref(root: Path, page: Path, what: str, ref: str, loaded: bool) -> str | None:
    """The problem with one address of ``page`` (None when there is none)."""
    ref = ref.strip()
    if not ref or ref.startswith("#"):
        return None
    parts = urlsplit(ref)
    where = f"{page.relative_to(root)}: {what} {ref[:120]}"
    if parts.scheme:
        if parts.scheme.lower() in LOCAL_SCHEMES:
            return None
        if loaded:
            return f"{where}: loaded from the network"
        return None  # a link a reader may follow out of the site
    if ref.startswith("//"):
        return f"{where}: {'loaded from the network' if loaded else 'a link to another host'}"
    if ref.startswith("/"):
        return f"{where}: a root-absolute address (breaks when the site is served from a folder)"
    if not parts.path:
        return None
    target = (page.parent / unquote(parts.path)).resolve()
    try:
        target.relative_to(root)
    except ValueError:
        return f"{where}: leaves the site"
    if target.is_dir():
        target = target / "index.html"
    if not target.exists():
        return f"{where}: no such file in the site"
    return None


def check_site(root: Path) -> tuple[list[str], int]:
    """The problems of the site in ``root`` (see the module) and the number of pages read."""
    root = root.resolve()
    if not (root / "index.html").is_file():
        return [f"{root}: no index.html (build the site first: make site)"], 0
    problems: list[str] = []
    pages = 0
    for path in sorted(root.rglob("*")):
        if not path.is_file():
            continue
        suffix = path.suffix.lower()
        if suffix not in (".html", ".css", ".js", ".mjs"):
            continue
        text = path.read_text(encoding="utf-8", errors="replace")
        if LOOPBACK.search(text):
            m = LOOPBACK.search(text)
            assert m is not None
            near = text[max(0, m.start() - 40) : m.end() + 40].replace("\n", " ")
            problems.append(f"{path.relative_to(root)}: a loopback address: ...{near}...")
        if suffix == ".html" and path.relative_to(root).parts[0] != "_static":
            pages += 1
            parser = _Refs()
            parser.feed(text)
            refs = parser.refs + [
                ("css url()", r, True) for style in parser.styles for r in _css_refs(style)
            ]
        elif suffix == ".css":
            refs = [("css url()", r, True) for r in _css_refs(text)]
        else:
            continue
        for what, ref, loaded in refs:
            problem = _check_ref(root, path, what, ref, loaded)
            if problem is not None:
                problems.append(problem)
    return problems, pages


def main(argv: list[str]) -> int:
    if len(argv) != 1:
        print("usage: python docs/_ext/check_site.py SITE_DIR", file=sys.stderr)
        return 2
    problems, pages = check_site(Path(argv[0]))
    for p in problems:
        print(f"check_site: {p}", file=sys.stderr)
    if problems:
        print(f"check_site: {len(problems)} problems in {argv[0]}", file=sys.stderr)
        return 1
    print(
        f"check_site: {pages} pages in {argv[0]}: relative addresses only, every one inside the "
        "site, nothing loaded from the network, no loopback address"
    )
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
