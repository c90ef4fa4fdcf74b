"""Check that environment.lock installs on every supported platform and Python version.

Usage: ``.venv/bin/python .ci/lock_platforms.py [--lock environment.lock] [--index URL] [--uv .venv/bin/uv]``.

1. Wheels. For every package of the lock, the sha256 hashes of the lock are matched against the files the
   package index lists for the package (PEP 691 JSON simple API), which names each hashed file. A package has
   compiled code when one of its locked files is a platform wheel. For each such package and each target
   (CPython 3.11, 3.12, 3.13 on manylinux x86_64/aarch64 with glibc 2.28, macOS 14 x86_64/arm64, and
   Windows x86_64 for information) where its marker applies, a locked wheel must install there
   (``packaging.tags``: the target's tags against the wheel's). The table lists every compiled package: ``ok``,
   ``MISSING`` (no locked wheel: pip would have to compile the sdist) or ``-`` (the marker excludes the target).
2. Resolution. For each Python version and platform, ``uv pip compile environment.lock --python-version V
   --python-platform P`` resolves the lock's pins with their dependencies; the result must be exactly the pins
   whose markers apply there (nothing added, nothing changed), so the lock is complete for that target.

Exit status 0 when every required cell is ``ok`` and every resolution matches, 1 otherwise. Needs the network
(the package index); the offline half of the check (the lock satisfies pyproject.toml) is in
tests/test_packaging.py, which imports :func:`read_lock` and :data:`TARGETS` from here.
"""

from __future__ import annotations

import argparse
import json
import os
import re
import ssl
import subprocess
import sys
import urllib.request
from dataclasses import dataclass
from pathlib import Path

from packaging.markers import Marker
from packaging.tags import Tag, compatible_tags, cpython_tags, mac_platforms
from packaging.utils import canonicalize_name, parse_wheel_filename

ROOT = Path(__file__).resolve().parents[1]
PYTHONS = ((3, 11), (3, 12), (3, 13))
GLIBC_MINOR = 28  # manylinux_2_28: glibc 2.28 (Debian 10, RHEL 8, Ubuntu 18.10) and later
MACOS = (14, 0)  # macOS 14 Sonoma


@dataclass(frozen=True)
class Platform:
    """One operating system and architecture: its PEP 425 platform tags and its PEP 508 marker values."""

    name: str
    uv: str  # uv's --python-platform
    tags: tuple[str, ...]  # most specific first
    sys_platform: str
    machine: str
    required: bool = True  # Windows is reported, not required


def _manylinux(arch: str) -> tuple[str, ...]:
    """PEP 600 tags of a glibc 2.GLIBC_MINOR Linux, newest first, with the legacy aliases (PEP 513, 571, 599)."""
    tags = [f"manylinux_2_{minor}_{arch}" for minor in range(GLIBC_MINOR, 4, -1)]
    legacy = {"manylinux2014": 17, "manylinux2010": 12, "manylinux1": 5}
    aliases = [f"{alias}_{arch}" for alias, minor in legacy.items() if arch in ("x86_64", "i686") or minor == 17]
    return tuple(tags + aliases)


PLATFORMS = (
    Platform("manylinux x86_64", "x86_64-manylinux_2_28", _manylinux("x86_64"), "linux", "x86_64"),
    Platform("manylinux aarch64", "aarch64-manylinux_2_28", _manylinux("aarch64"), "linux", "aarch64"),
    Platform("macOS x86_64", "x86_64-apple-darwin", tuple(mac_platforms(MACOS, "x86_64")), "darwin", "x86_64"),
    Platform("macOS arm64", "aarch64-apple-darwin", tuple(mac_platforms(MACOS, "arm64")), "darwin", "arm64"),
    Platform("Windows x86_64", "x86_64-pc-windows-msvc", ("win_amd64",), "win32", "AMD64", required=False),
)
TARGETS = tuple((python, platform) for platform in PLATFORMS for python in PYTHONS)


@dataclass(frozen=True)
class Pin:
    """One requirement line of the lock: name==version, its marker (None: everywhere) and its sha256 hashes."""

    name: str
    version: str
    marker: Marker | None
    hashes: tuple[str, ...]


def read_lock(text: str) -> list[Pin]:
    """Every pin of a ``uv pip compile --generate-hashes`` file (a pin line and its continuation lines)."""
    pins = []
    for block in re.split(r"\n(?=[A-Za-z0-9])", text):
        head = re.match(r"([A-Za-z0-9._-]+)==([^\s;\\]+)(?:\s*;\s*([^\\\n]+?))?\s*\\?\n", block)
        if head:
            marker = Marker(head[3]) if head[3] else None
            hashes = tuple(re.findall(r"--hash=sha256:([0-9a-f]{64})", block))
            pins.append(Pin(canonicalize_name(head[1]), head[2], marker, hashes))
    return pins


def marker_environment(python: tuple[int, int], platform: Platform) -> dict[str, str]:
    """The PEP 508 marker variables of CPython ``python`` on ``platform``."""
    version = f"{python[0]}.{python[1]}"
    system = {"linux": "Linux", "darwin": "Darwin", "win32": "Windows"}[platform.sys_platform]
    return {
        "implementation_name": "cpython", "implementation_version": f"{version}.0", "os_name":
        "nt" if platform.sys_platform == "win32" else "posix", "platform_machine": platform.machine,
        "platform_python_implementation": "CPython", "platform_release": "", "platform_system": system,
        "platform_version": "", "python_full_version": f"{version}.0", "python_version": version,
        "sys_platform": platform.sys_platform, "extra": "",
    }


def applies(pin: Pin, python: tuple[int, int], platform: Platform) -> bool:
    """Whether pip installs ``pin`` for ``python`` on ``platform`` (its marker holds there)."""
    return pin.marker is None or pin.marker.evaluate(marker_environment(python, platform))


def target_tags(python: tuple[int, int], platform: Platform) -> set[Tag]:
    """Every wheel tag CPython ``python`` installs on ``platform`` (PEP 425, as pip orders them)."""
    return set(cpython_tags(python, platforms=platform.tags)) | set(
        compatible_tags(python, f"cp{python[0]}{python[1]}", platforms=platform.tags)
    )


def is_platform_wheel(filename: str) -> bool:
    """A wheel with compiled code: its tags name a platform other than ``any``."""
    return filename.endswith(".whl") and any(tag.platform != "any" for tag in parse_wheel_filename(filename)[3])


def installs(filenames: list[str], python: tuple[int, int], platform: Platform) -> bool:
    """Whether one of the wheels ``filenames`` installs for ``python`` on ``platform``."""
    tags = target_tags(python, platform)
    return any(set(parse_wheel_filename(f)[3]) & tags for f in filenames if f.endswith(".whl"))


def index_files(index: str, name: str) -> dict[str, str]:
    """sha256 -> file name of every file the index lists for ``name`` (PEP 691 JSON simple API)."""
    request = urllib.request.Request(f"{index.rstrip('/')}/{name}/",
                                     headers={"Accept": "application/vnd.pypi.simple.v1+json"})
    cafile = os.environ.get("PIP_CERT") or os.environ.get("SSL_CERT_FILE")
    with urllib.request.urlopen(request, timeout=120, context=ssl.create_default_context(cafile=cafile)) as answer:
        files = json.load(answer)["files"]
    return {f["hashes"]["sha256"]: f["filename"] for f in files if "sha256" in f.get("hashes", {})}


def wheel_row(pin: Pin, filenames: list[str]) -> tuple[list[str], int, int]:
    """Cells of one compiled package, one per platform (the Python versions it installs on); required cells, gaps."""
    cells, required, gaps = [], 0, 0
    for platform in PLATFORMS:
        marks = []
        for python in PYTHONS:
            if not applies(pin, python, platform):
                marks.append("-")
                continue
            found = installs(filenames, python, platform)
            marks.append("ok" if found else "MISSING")
            required += platform.required
            gaps += platform.required and not found
        cells.append("/".join(marks))
    return cells, required, gaps


def check_wheels(pins: list[Pin], index: str) -> int:
    """Print the wheel table of the compiled packages and the counts; return the number of required gaps."""
    header = ["package", "version"] + [p.name + ("" if p.required else " (info)") for p in PLATFORMS]
    rows, required, gaps, pure, sdist_only, unknown = [], 0, 0, 0, [], []
    for pin in pins:
        known = index_files(index, pin.name)
        filenames = [known[h] for h in pin.hashes if h in known]
        unknown += [f"{pin.name}=={pin.version}: {h}" for h in pin.hashes if h not in known]
        sdist_only += [pin.name] if not any(f.endswith(".whl") for f in filenames) else []
        if not any(map(is_platform_wheel, filenames)):
            pure += 1
            continue
        cells, row_required, row_gaps = wheel_row(pin, filenames)
        rows.append([pin.name, pin.version] + cells)
        required, gaps = required + row_required, gaps + row_gaps
    widths = [max(len(row[i]) for row in [header] + rows) for i in range(len(header))]
    print("cells: cp311/cp312/cp313; ok = a locked wheel installs, - = the pin's marker excludes the target")
    for row in [header] + rows:
        print("  ".join(cell.ljust(width) for cell, width in zip(row, widths, strict=True)))
    print(f"\n{len(pins)} pins: {len(rows)} with compiled code, {pure} pure Python ({len(sdist_only)} of them "
          f"locked as an sdist only: {', '.join(sdist_only) or 'none'}); {required} required cells "
          f"(package, Python, platform) where a pin applies, {required - gaps} with a locked wheel, {gaps} missing; "
          f"{len(unknown)} locked hashes unknown to the index")
    for line in unknown:
        print("  unknown hash:", line)
    return gaps + len(unknown)


def check_resolution(pins: list[Pin], lock: Path, uv: str) -> int:
    """Resolve the lock with uv for every target; return the number of targets whose resolution differs."""
    failures = 0
    for python, platform in TARGETS:
        wanted = {f"{p.name}=={p.version}" for p in pins if applies(p, python, platform)}
        version = f"{python[0]}.{python[1]}"
        run = subprocess.run([uv, "pip", "compile", str(lock), "--python-version", version, "--python-platform",
                              platform.uv, "--no-header", "--no-annotate", "--quiet"],
                             capture_output=True, text=True, check=False)
        got = {canonicalize_name(n) + "==" + v for n, v in re.findall(r"^([A-Za-z0-9._-]+)==(\S+)", run.stdout, re.M)}
        same = run.returncode == 0 and got == wanted
        failures += not same and platform.required
        detail = "ok" if same else (f"DIFFERS: {run.stderr.strip()[-300:]} added {sorted(got - wanted)[:5]}"
                                    f" absent {sorted(wanted - got)[:5]}")
        print(f"resolve CPython {version} {platform.name:<18} {len(got):4d} pins  {detail}")
    return failures


def main() -> int:
    """Run both checks on the lock and print their tables and counts."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--lock", type=Path, default=ROOT / "environment.lock")
    parser.add_argument("--index", default="https://pypi.org/simple")
    parser.add_argument("--uv", default=str(Path(sys.executable).with_name("uv")))
    args = parser.parse_args()
    pins = read_lock(args.lock.read_text(encoding="utf-8"))
    gaps = check_wheels(pins, args.index)
    failures = check_resolution(pins, args.lock, args.uv)
    print(f"\n{'PASS' if gaps == failures == 0 else 'FAIL'}: {gaps} wheel gaps or unknown hashes, "
          f"{failures} required targets whose resolution differs from the lock")
    return int(gaps + failures > 0)


if __name__ == "__main__":
    sys.exit(main())
