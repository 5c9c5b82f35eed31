"""The prism-to-hex route of gmsh_validity.py must be able to fail: for prisms of order 3 and 4,
io_write_samples writes a valid curved prism and a folded one (det J = 1 - 3y changes sign inside);
Gmsh, through the three hex pieces, must find the first valid and the second invalid.

usage: verify_gmsh_validity.py IO_WRITE_SAMPLES
"""
import os
import sys

here = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, here)
sys.path.insert(0, os.path.join(here, "..", "io"))
from gmsh_validity import certified_ratios  # noqa: E402
from sample_map import Failures, write_samples  # noqa: E402


def main():
    samples = write_samples(sys.argv[1])
    f = Failures()
    for p in (3, 4):  # 5 and 6 work too, but Gmsh builds its order-6 hex Bezier tables for minutes
        for name, expect_valid in (("pri_%d.msh" % p, True), ("pri_%d_invalid.msh" % p, False)):
            result = certified_ratios(os.path.join(samples, name), processes=1)
            f.check(len(result["prisms"]) == 1 and not result["direct"], "%s: %s" % (name, result))
            worst = min(result["prisms"])
            f.check((worst > 0) == expect_valid, "%s: gmsh's worst piece min J / max J = %g" % (name, worst))
            print("%s: worst piece %.4g" % (name, worst))
    f.finish("verify_gmsh_validity")


if __name__ == "__main__":
    main()
