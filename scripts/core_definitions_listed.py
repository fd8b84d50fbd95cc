#!/usr/bin/env python3
# Copyright (c) 2026 The CGAL Symmetry_transform project.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Checks that src/Symmetry_transform/precompiled_core.cpp includes every header of include/ whose
definitions are hidden from the users of the precompiled core (CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS):
one left out would leave its functions undefined at link time in a program that calls them; and that
each such header includes internal/common/core_definitions.h before it uses its macros (an undefined
CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS would drop the definitions silently).

    python3 scripts/core_definitions_listed.py [ROOT]
"""

import pathlib
import re
import sys

ROOT = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parent.parent)
MACROS = ROOT / "include/CGAL/Symmetry_transform/internal/common/core_definitions.h"
CORE = ROOT / "src/Symmetry_transform/precompiled_core.cpp"

MACRO_INCLUDE = "#include <CGAL/Symmetry_transform/internal/common/core_definitions.h>"


def includes(text):
    return set(re.findall(r"^#include <([^>]+)>", text, re.MULTILINE))


hiding, unprepared = set(), []
for path in sorted((ROOT / "include").rglob("*.h")):
    text = path.read_text()
    uses = [text.find(m) for m in ("CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS", "CGAL_SYMMETRY_TRANSFORM_CORE_INLINE")]
    uses = [u for u in uses if u >= 0]
    if path == MACROS or not uses:
        continue
    name = str(path.relative_to(ROOT / "include"))
    hiding.add(name)
    where = text.find("\n" + MACRO_INCLUDE)
    if where < 0 or where > min(uses):
        unprepared.append(name)
missing = sorted(hiding - includes(CORE.read_text()))
for header in missing:
    print(f"{CORE.relative_to(ROOT)} does not include {header}, whose definitions it must compile")
for header in unprepared:
    print(f"{header} uses the macros of core_definitions.h without including it first")
print(f"{len(hiding)} headers with hidden definitions, {len(missing)} not included, {len(unprepared)} without the macros")
sys.exit(1 if missing or unprepared or not hiding else 0)
