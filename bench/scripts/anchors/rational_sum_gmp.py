#!/usr/bin/env python3
"""rational-sum in C on GMP's mpq_t (rational_sum_gmp.c): builds the program once against the libgmp that gmpy2
bundles (a C compiler is needed; the build goes beside this virtual environment's Python) and
runs it.

Usage: rational_sum_gmp.py MODE [COUNT]     (as rational_sum.py; prints its one JSON line)
"""
import glob
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def build():
    import gmpy2

    # The real path: a virtual environment reached through a symbolic link must not leave the
    # link's path in the program's rpath (the link may go away).
    libs = os.path.realpath(os.path.join(os.path.dirname(os.path.dirname(gmpy2.__file__)), "gmpy2.libs"))
    found = sorted(glob.glob(os.path.join(libs, "libgmp*.so*")))
    if not found:
        raise SystemExit("rational_sum_gmp: gmpy2's bundled libgmp was not found")
    src = os.path.join(HERE, "rational_sum_gmp.c")
    exe = os.path.join(os.path.dirname(sys.executable), "rational_sum_gmp")
    # The program finds libgmp through the rpath of the directory it was built against: rebuilt
    # when that directory changed (a virtual environment reached through another path).
    stamp = exe + ".libdir"
    built_for = open(stamp).read() if os.path.exists(stamp) else None
    if (not os.path.exists(exe) or os.path.getmtime(exe) < os.path.getmtime(src)
            or built_for != libs):
        cc = os.environ.get("CC", "cc")
        cmd = [cc, "-O2", "-o", exe, src, "-L", libs, "-l:" + os.path.basename(found[0]),
               "-Wl,-rpath," + libs]
        done = subprocess.run(cmd, capture_output=True, text=True)
        if done.returncode != 0:
            raise SystemExit(f"rational_sum_gmp: `{' '.join(cmd)}` failed: {done.stderr.strip()[-400:]}")
        with open(stamp, "w") as f:
            f.write(libs)
    return exe


def main():
    if len(sys.argv) not in (2, 3):
        raise SystemExit(__doc__)
    exe = build()
    n = sys.argv[2] if len(sys.argv) == 3 else "100000"
    sys.exit(subprocess.run([exe, sys.argv[1], n]).returncode)


if __name__ == "__main__":
    main()
