#!/usr/bin/env python3
# Copyright (c) 2026 The CGAL Symmetry_transform project.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Checks that src/Symmetry_transform/precompiled_core.cpp includes every header of include/ whose
definitions are hidden from the users of the precompiled core (CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS):
one left out would leave its functions undefined at link time in a program that calls them.

    python3 scripts/core_definitions_listed.py [ROOT]
"""

import pathlib
import re
import sys

ROOT = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parent.parent)
MACROS = ROOT / "include/CGAL/Symmetry_transform/internal/common/core_definitions.h"
CORE = ROOT / "src/Symmetry_transform/precompiled_core.cpp"

hiding = {str(p.relative_to(ROOT / "include")) for p in (ROOT / "include").rglob("*.h")
          if p != MACROS and "#if CGAL_SYMMETRY_TRANSFORM_CORE_DEFINITIONS" in p.read_text()}
included = set(re.findall(r"#include <([^>]+)>", CORE.read_text()))
missing = sorted(hiding - included)
for header in missing:
    print(f"{CORE.relative_to(ROOT)} does not include {header}, whose definitions it must compile")
print(f"{len(hiding)} headers with hidden definitions, {len(missing)} not included")
sys.exit(1 if missing or not hiding else 0)
