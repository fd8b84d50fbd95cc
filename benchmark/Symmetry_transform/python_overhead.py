"""The cost of calling the package from Python: principal_symmetries() on a mesh, against the C++
demo program principal_symmetries timing the same detection of the same soup, alternately, in
one run, each call in a process of its own. Both with the defaults (64^3, both cores), ten planes at most; the Python call skips the
symmetry distance errors (sde_samples=0), which the demo's timing leaves out too.

    build/python-venv/bin/python benchmark/Symmetry_transform/python_overhead.py \
        --demo build/demo/Symmetry_transform/principal_symmetries --mesh build/data/meshes/bull.off
"""

import argparse
import re
import statistics
import subprocess
import sys
import time

import symmetry_transform as st


def cpp_seconds(demo: str, mesh: str) -> float:
    out = subprocess.run([demo, mesh, "--planes", "10", "--output", "/dev/null"], capture_output=True, text=True,
                         check=True).stdout
    return float(re.search(r"principal symmetries \(grid .*\) in (\S+) s", out).group(1))


def python_seconds(mesh: str) -> float:
    """The call timed in a process of its own, as the demo's: both start as cold."""
    out = subprocess.run([sys.executable, __file__, "--call", mesh], capture_output=True, text=True, check=True).stdout
    return float(out)


def timed_call(mesh: str) -> float:
    vertices, faces = st.read_mesh(mesh)
    start = time.perf_counter()
    st.principal_symmetries(vertices, faces, max_number_of_planes=10, sde_samples=0)
    return time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--demo", help="the C++ program demo/Symmetry_transform/principal_symmetries")
    parser.add_argument("--mesh")
    parser.add_argument("--repeats", type=int, default=7)
    parser.add_argument("--call", metavar="MESH", help=argparse.SUPPRESS)  # one timed call, in a child
    args = parser.parse_args()
    if args.call:
        print(timed_call(args.call))
        return
    if not args.demo or not args.mesh:
        parser.error("--demo and --mesh are required")
    cpp, python = [], []
    for _ in range(args.repeats):
        cpp.append(cpp_seconds(args.demo, args.mesh))
        python.append(python_seconds(args.mesh))
    c, p = statistics.median(cpp), statistics.median(python)
    print(f"| mesh | C++ median (s) | Python median (s) | Python / C++ |\n|---|---:|---:|---:|")
    print(f"| {args.mesh.split('/')[-1]} | {c:.3f} | {p:.3f} | {p / c:.3f} |")
    print(f"C++ runs: {' '.join(f'{x:.3f}' for x in cpp)}; Python runs: {' '.join(f'{x:.3f}' for x in python)}")


if __name__ == "__main__":
    main()
