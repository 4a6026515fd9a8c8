"""The cross-built Linux aarch64 wheel (`make wheel-aarch64`, issue 23, item 1), inspected as
auditwheel would read it, since this x86-64 machine cannot run it: its WHEEL tags, the extension's
ELF header (64-bit, little-endian, ARM aarch64), the glibc symbol versions it needs (none newer than
its manylinux tag allows) and the shared libraries it links (only those every manylinux system
has), and the built lab inside.

`make wheel-aarch64` runs this file with POINSOT_WHEEL_AARCH64 naming the wheel; without it these
tests are skipped (and `make test-python` deselects them: marker `wheel`).
"""

from __future__ import annotations

import os
import re
import struct
import zipfile
from pathlib import Path

import pytest

pytestmark = pytest.mark.wheel

WHEEL = os.environ.get("POINSOT_WHEEL_AARCH64", "")
EM_AARCH64 = 183
# The libraries a manylinux wheel may link without carrying them (PEP 599's list, as far as a
# Rust extension can use it).
MANYLINUX_LIBS = {"libc.so.6", "libm.so.6", "libpthread.so.0", "libdl.so.2", "libgcc_s.so.1"}


@pytest.fixture(scope="module")
def wheel() -> Path:
    if not WHEEL:
        pytest.skip("needs the aarch64 wheel: run `make wheel-aarch64`")
    path = Path(WHEEL).resolve()
    assert path.is_file(), f"POINSOT_WHEEL_AARCH64={WHEEL!r} is not a file"
    return path


@pytest.fixture(scope="module")
def extension(wheel: Path) -> bytes:
    with zipfile.ZipFile(wheel) as zf:
        names = [n for n in zf.namelist() if re.fullmatch(r"poinsot/_core\.abi3\.so", n)]
        assert names, zf.namelist()
        return zf.read(names[0])


def _sections(elf: bytes) -> dict[str, tuple[int, int, int]]:
    """Name → (type, offset, size) of each section of a 64-bit little-endian ELF file."""
    (shoff,) = struct.unpack_from("<Q", elf, 0x28)
    shentsize, shnum, shstrndx = struct.unpack_from("<HHH", elf, 0x3A)
    headers = [struct.unpack_from("<IIQQQQIIQQ", elf, shoff + i * shentsize) for i in range(shnum)]
    names_at = headers[shstrndx][4]
    out = {}
    for name, kind, _, _, offset, size, *_ in headers:
        end = elf.index(b"\0", names_at + name)
        out[elf[names_at + name : end].decode()] = (kind, offset, size)
    return out


def _needed(elf: bytes) -> set[str]:
    """The DT_NEEDED entries of the dynamic section."""
    sections = _sections(elf)
    _, dyn_at, dyn_size = sections[".dynamic"]
    _, str_at, _ = sections[".dynstr"]
    out = set()
    for tag, value in struct.iter_unpack("<qQ", elf[dyn_at : dyn_at + dyn_size]):
        if tag == 0:
            break
        if tag == 1:  # DT_NEEDED
            out.add(elf[str_at + value : elf.index(b"\0", str_at + value)].decode())
    return out


def test_tags_say_aarch64_manylinux_2_17(wheel: Path) -> None:
    assert re.fullmatch(r"poinsot-[^-]+-cp39-abi3-[^-]*manylinux_2_17_aarch64\.whl", wheel.name)
    with zipfile.ZipFile(wheel) as zf:
        meta = next(n for n in zf.namelist() if n.endswith(".dist-info/WHEEL"))
        tags = re.findall(r"^Tag: (\S+)$", zf.read(meta).decode(), re.MULTILINE)
    assert "cp39-abi3-manylinux_2_17_aarch64" in tags, tags
    assert all(t.endswith("aarch64") for t in tags), tags


def test_extension_is_arm64_and_asks_no_newer_glibc(extension: bytes) -> None:
    assert extension[:4] == b"\x7fELF"
    assert extension[4] == 2 and extension[5] == 1, "64-bit, little-endian"
    (machine,) = struct.unpack_from("<H", extension, 18)
    assert machine == EM_AARCH64, machine
    versions = {
        tuple(int(x) for x in v.split(b"."))
        for v in re.findall(rb"GLIBC_(\d+\.\d+(?:\.\d+)?)\0", extension)
    }
    assert versions and max(versions) <= (2, 17), sorted(versions)
    assert _needed(extension) <= MANYLINUX_LIBS, _needed(extension)


def test_carries_the_package_and_the_lab(wheel: Path) -> None:
    with zipfile.ZipFile(wheel) as zf:
        names = set(zf.namelist())
        assert {"poinsot/__init__.py", "poinsot/_core.pyi", "poinsot/lab/index.html"} <= names
        assert any(n.startswith("poinsot/lab/") and n.endswith(".wasm") for n in names)
        assert all(n.startswith(("poinsot/", "poinsot-")) for n in names)
        assert zf.read("poinsot/lab/index.html")[:15].lower() == b"<!doctype html>"
