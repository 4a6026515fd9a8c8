"""The server of `poinsot lab`: loopback only, the page's own files only (issue 6).

These tests need no built page: they serve a temporary directory of files, with a secret file
next to it that must never come back.
"""

from __future__ import annotations

import http.client
import os
import socket
import threading
from collections.abc import Iterator
from pathlib import Path

import pytest
from click.testing import CliRunner

from poinsot import _labserver
from poinsot._labserver import LabServer, resolve_request, start_in_thread
from poinsot.cli import main

SECRET = b"outside the page: must never be served\n"


@pytest.fixture()
def site(tmp_path: Path) -> Path:
    root = tmp_path / "page"
    (root / "assets").mkdir(parents=True)
    (root / "index.html").write_bytes(b"<!doctype html><title>lab</title>")
    (root / "assets" / "app.js").write_bytes(b"export const x = 1;\n")
    (root / "assets" / "core.wasm").write_bytes(b"\x00asm\x01\x00\x00\x00")
    (tmp_path / "secret.txt").write_bytes(SECRET)
    (tmp_path / "page-sibling").mkdir()
    (tmp_path / "page-sibling" / "x.txt").write_bytes(SECRET)
    return root


@pytest.fixture()
def server(site: Path) -> Iterator[LabServer]:
    srv = start_in_thread(site)
    yield srv
    srv.shutdown()
    srv.server_close()


def request(srv: LabServer, path: str, method: str = "GET", host: str | None = None) -> tuple[int, bytes, dict[str, str]]:
    """Send `path` verbatim (http.client does not normalise it) and return status, body, headers."""
    conn = http.client.HTTPConnection("127.0.0.1", srv.server_address[1], timeout=5)
    try:
        conn.putrequest(method, path, skip_host=host is not None)
        if host is not None:
            conn.putheader("Host", host)
        conn.endheaders()
        resp = conn.getresponse()
        return resp.status, resp.read(), {k.lower(): v for k, v in resp.getheaders()}
    finally:
        conn.close()


def test_serves_the_page_and_its_assets_with_their_types(server: LabServer) -> None:
    status, body, headers = request(server, "/")
    assert status == 200 and body.startswith(b"<!doctype html>")
    assert headers["content-type"].startswith("text/html")
    assert headers["x-content-type-options"] == "nosniff"
    assert "wasm-unsafe-eval" in headers["content-security-policy"]
    status, _, headers = request(server, "/assets/app.js?v=1#frag")
    assert status == 200 and headers["content-type"].startswith("text/javascript")
    status, body, headers = request(server, "/assets/core.wasm")
    assert status == 200 and headers["content-type"] == "application/wasm" and body.startswith(b"\x00asm")
    status, body, _ = request(server, "/index.html", method="HEAD")
    assert status == 200 and body == b""


TRAVERSALS = [
    "/../secret.txt",
    "/assets/../../secret.txt",
    "/assets/../index.html",  # even inside: no `..` segments at all
    "/./index.html",
    "/%2e%2e/secret.txt",
    "/%2E%2E/secret.txt",
    "/assets/%2e%2e/%2e%2e/secret.txt",
    "/..%2fsecret.txt",
    "/..%2Fsecret.txt",
    "/%2e%2e%2fsecret.txt",
    "/..%5csecret.txt",
    "/..\\secret.txt",
    "/%252e%252e/secret.txt",
    "/index.html%00",
    "/../page-sibling/x.txt",
    "/../page/../secret.txt",
    "//secret.txt",
    "/assets",  # a directory, not a file
    "/missing.html",
    "secret.txt",  # not origin-form
    "http://example.com/../secret.txt",
]


@pytest.mark.parametrize("path", TRAVERSALS)
def test_nothing_outside_the_page_is_served(server: LabServer, path: str) -> None:
    status, body, _ = request(server, path)
    assert status == 404, (path, status)
    assert SECRET not in body


def test_absolute_paths_of_real_files_are_not_served(server: LabServer, site: Path) -> None:
    secret = (site.parent / "secret.txt").resolve()
    status, body, _ = request(server, "/" + str(secret).lstrip("/"))
    assert status == 404 and SECRET not in body
    status, _, _ = request(server, str(secret))
    assert status == 404


@pytest.mark.skipif(not hasattr(os, "symlink"), reason="no symbolic links")
def test_symlinks_leading_outside_are_not_followed(site: Path) -> None:
    (site / "link.txt").symlink_to(site.parent / "secret.txt")
    (site / "linkdir").symlink_to(site.parent / "page-sibling", target_is_directory=True)
    srv = start_in_thread(site)
    try:
        for path in ("/link.txt", "/linkdir/x.txt"):
            status, body, _ = request(srv, path)
            assert status == 404 and SECRET not in body
    finally:
        srv.shutdown()
        srv.server_close()


def test_resolve_request_negative_control(site: Path) -> None:
    # The same resolver does find files that are inside (so the 404s above are not vacuous).
    assert resolve_request(site, "/assets/app.js") == (site / "assets" / "app.js").resolve()
    assert resolve_request(site, "/") == (site / "index.html").resolve()
    assert resolve_request(site, "/assets/../assets/app.js") is None


def test_binds_to_loopback_only(server: LabServer, site: Path) -> None:
    assert server.server_address[0] == "127.0.0.1"
    assert server.url.startswith("http://127.0.0.1:")
    for host in ("0.0.0.0", "", "::", "localhost", "192.168.1.2"):
        with pytest.raises(ValueError, match="host: the lab binds to 127.0.0.1 only"):
            LabServer(site, 0, host=host)
    # Not reachable through any other local address of this machine.
    try:
        others = {ai[4][0] for ai in socket.getaddrinfo(socket.gethostname(), None, socket.AF_INET)} - {"127.0.0.1"}
    except OSError:
        others = set()
    for addr in sorted(a for a in others if not a.startswith("127.")):
        with pytest.raises(OSError):
            socket.create_connection((addr, server.server_address[1]), timeout=1).close()


def test_other_methods_and_foreign_hosts_are_refused(server: LabServer) -> None:
    assert request(server, "/", method="POST")[0] == 405
    assert request(server, "/", method="DELETE")[0] == 405
    status, body, _ = request(server, "/", host="evil.example:80")
    assert status == 404 and b"doctype" not in body
    port = server.server_address[1]
    assert request(server, "/", host=f"localhost:{port}")[0] == 200


def test_bad_port_is_refused(site: Path) -> None:
    with pytest.raises(ValueError, match="port"):
        LabServer(site, 70000)


def test_cli_without_a_built_page_says_how_to_build_it(monkeypatch: pytest.MonkeyPatch, tmp_path: Path) -> None:
    monkeypatch.setattr(_labserver, "page_dir", lambda: tmp_path / "nothing")
    result = CliRunner().invoke(main, ["lab", "--no-browser"])
    assert result.exit_code != 0
    assert "make lab" in result.output


def test_cli_serves_the_page_and_does_not_open_a_browser_when_told(
    monkeypatch: pytest.MonkeyPatch, site: Path
) -> None:
    monkeypatch.setattr(_labserver, "page_dir", lambda: site)
    opened: list[str] = []
    monkeypatch.setattr("webbrowser.open", lambda url, *a, **k: opened.append(url))
    served: list[tuple[str, int]] = []

    def serve_once(self: LabServer, poll_interval: float = 0.5) -> None:
        status: list[int] = []
        client = threading.Thread(target=lambda: status.append(request(self, "/")[0]))
        client.start()
        self.handle_request()
        client.join(5)
        served.append((self.url, status[0] if status else 0))
        raise KeyboardInterrupt

    monkeypatch.setattr(LabServer, "serve_forever", serve_once)
    result = CliRunner().invoke(main, ["lab", "--no-browser"])
    assert result.exit_code == 0, result.output
    assert opened == []
    assert served and served[0][1] == 200 and served[0][0].startswith("http://127.0.0.1:")
    assert "serving http://127.0.0.1:" in result.output

    result = CliRunner().invoke(main, ["lab"])
    assert result.exit_code == 0 and len(opened) == 1 and opened[0].startswith("http://127.0.0.1:")
