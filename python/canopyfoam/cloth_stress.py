"""cloth_stress.py — the inflated cloth's membrane stress by ring (meridional and hoop, from the springs' tensions in canopy.h5) and the skirt's scallops between the suspension lines, against tension-field theory and a taut hem.

The stress. A spring network's mean stress over an area A is its virial,
sigma = (1/A) sum_e T_e l_e (e_e outer e_e), T_e the spring's tension, l_e
its length and e_e its unit vector (the Irving-Kirkwood / virial stress of
a pair-force network, e.g. Tadmor & Miller, Modeling Materials, 2011,
ch. 8). Each cloth spring gives half of T_e l_e to each of its (one or
two) triangles; a ring of the cloth (bins of the radial position s of
shape.py, by the triangle's mean s) sums its triangles' shares over their
area. The meridional and hoop directions are taken at each spring's
midpoint: the hoop direction h is the canopy's axis (shape.py's, payload
to the cloth's mean) crossed with the midpoint's offset from it, the
meridional m = h x n with n the mean normal of the spring's triangles.
Then sigma_mm = sum T l (e.m)^2 / A and sigma_hh = sum T l (e.h)^2 / A
(N/m). On a polar mesh a spoke lies along m and a ring's chord along h
exactly, which the tests use.

What it checks. Tension-field theory (tension_field_shape.py) takes the
gathered cloth to carry no hoop stress, sigma_hh = 0, and the meridional
stress to fall as 1/r, r sigma_mm = C, the canopy's drag over 2 pi. The
ring table gives both, with the fraction of the ring's triangles whose
hoop stress is below a tenth of their meridional one (wrinkled). The
theory also takes the pressure jump across the cloth as uniform; the
table gives each ring's area-weighted mean of the jump the solver handed
the cloth (canopy.h5's dp, one value a triangle) beside the cloth's mean.

The scallops. Between two lines the skirt's hem (rest length L a gore)
spans a chord c = 2 r_a sin(pi / N) between attachments at radius r_a.
A taut hem bulging outward in the skirt's plane as a circular arc of
length L has half-angle theta with theta / sin(theta) = L / c, and its
outermost point lies at r_a cos(pi / N) + (c / 2) (1 - cos theta) /
sin theta (taut_hem_radius); a semicircle, L = pi c / 2, bulges by c / 2.
The measured skirt gives the attachments' mean radius and the largest
radius between them. The skirt's outline, the attachments' polygon with
the hem's circular segments, has area (N / 2) r_a^2 sin(2 pi / N) + N
rho^2 (theta - sin theta cos theta), rho = c / (2 sin theta) the arc's
radius; its equal-area diameter (taut_hem_outline_diameter) compares with
the silhouette's (shape.py) where the skirt is the canopy's widest
section, and for tension-field theory's attachments it gives the
projected diameter that theory's axisymmetric Dp leaves out.

Run as:  python3 -m canopyfoam.cloth_stress CASE T0 T1 [RINGS]
(from python/; needs h5py): the ring table averaged over the states
written in [T0, T1] (RINGS bins of s, 10 unless given) and the skirt's
scallops, lengths in R0 (the cloth's rest radius), and the skirt's
outline against tension-field theory's for the run's line length.
"""

import math
import sys

import numpy as np

from . import canopy_h5, shape
from .canopy_h5 import GROUP_FABRIC, GROUP_TAPE, GROUP_LINE

WRINKLED_HOOP_RATIO = 0.1


class ClothStressError(Exception):
    pass


class ClothSprings(object):
    """The cloth's springs with their triangles, the line attachments on
    the skirt and the hem's rest length, for a shape.CanopyMesh and its
    springs."""

    def __init__(self, mesh, springs, spring_groups, rest_lengths):
        springs = np.asarray(springs, dtype=int)
        groups = np.asarray(spring_groups, dtype=int)
        cloth = np.isin(groups, (GROUP_FABRIC, GROUP_TAPE))
        owners = shape.edges_of(mesh.triangles)
        index, share_tri, share_spring, share_weight = [], [], [], []
        for k in np.where(cloth)[0]:
            i, j = springs[k]
            tris = owners.get((min(i, j), max(i, j)), [])
            if not tris:
                continue
            index.append(k)
            for t in tris:
                share_tri.append(t)
                share_spring.append(len(index) - 1)
                share_weight.append(1.0 / len(tris))
        if not index:
            raise ClothStressError("no cloth spring lies on a triangle's "
                                   "edge")
        self.spring = np.array(index, dtype=int)
        self.ends = springs[self.spring]
        self.share_tri = np.array(share_tri, dtype=int)
        self.share_spring = np.array(share_spring, dtype=int)
        self.share_weight = np.array(share_weight)
        line_nodes = set(springs[groups == GROUP_LINE].ravel().tolist())
        self.attachments = np.array(sorted(set(mesh.skirt.tolist())
                                           & line_nodes), dtype=int)
        skirt = np.zeros(len(mesh.s), dtype=bool)
        skirt[mesh.skirt] = True
        hem = cloth & skirt[springs[:, 0]] & skirt[springs[:, 1]]
        self.hem_length = float(np.asarray(rest_lengths)[hem].sum())
        lines = groups == GROUP_LINE
        self.line_length = (float(np.asarray(rest_lengths)[lines].sum())
                            / len(self.attachments)
                            if len(self.attachments) else float("nan"))


def spring_directions(mesh, cloth_springs, x):
    """(e, length, m, h) per cloth spring of a state x: its unit vector and
    length, and the meridional and hoop unit vectors at its midpoint."""
    x = np.asarray(x, dtype=float)
    axis, _, _, _ = shape.axial_coordinates(mesh, x)
    centre = x[mesh.cloth_nodes].mean(axis=0)
    a, b = cloth_springs.ends[:, 0], cloth_springs.ends[:, 1]
    d = x[b] - x[a]
    length = np.linalg.norm(d, axis=1)
    e = d / length[:, None]
    normals = shape.triangle_normals(x, mesh.triangles)
    n = np.zeros((len(cloth_springs.spring), 3))
    np.add.at(n, cloth_springs.share_spring,
              normals[cloth_springs.share_tri])
    n /= np.linalg.norm(n, axis=1)[:, None]
    mid = 0.5 * (x[a] + x[b]) - centre
    h = np.cross(axis, mid)
    h /= np.linalg.norm(h, axis=1)[:, None]
    m = np.cross(h, n)
    m /= np.linalg.norm(m, axis=1)[:, None]
    return e, length, m, h


def _triangle_rings(mesh, x, edges):
    """(area, mean s, ring index) of each triangle in state x, the ring
    [edges[k], edges[k+1]) holding its mean s."""
    tx = np.asarray(x, dtype=float)[mesh.triangles]
    area = 0.5 * np.linalg.norm(np.cross(tx[:, 1] - tx[:, 0],
                                         tx[:, 2] - tx[:, 0]), axis=1)
    tri_s = mesh.s[mesh.triangles].mean(axis=1)
    ring = np.clip(np.searchsorted(edges, tri_s, side="right") - 1, 0,
                   len(edges) - 2)
    return area, tri_s, ring


def ring_stress(mesh, cloth_springs, x, tension, edges):
    """Per ring [edges[k], edges[k+1]) of the triangles' mean s: rows
    (s_mean, r_mean, sigma_mm, sigma_hh, wrinkled fraction) of the state
    x (nodes x 3) under the springs' tensions (all springs, N); r is the
    ring's mean node distance from the axis."""
    x = np.asarray(x, dtype=float)
    tension = np.asarray(tension, dtype=float)
    e, length, m, h = spring_directions(mesh, cloth_springs, x)
    tl = tension[cloth_springs.spring] * length
    along_m = tl * np.einsum("ij,ij->i", e, m) ** 2
    along_h = tl * np.einsum("ij,ij->i", e, h) ** 2
    nt = len(mesh.triangles)
    w = cloth_springs.share_weight
    tri_mm = np.zeros(nt)
    tri_hh = np.zeros(nt)
    np.add.at(tri_mm, cloth_springs.share_tri,
              w * along_m[cloth_springs.share_spring])
    np.add.at(tri_hh, cloth_springs.share_tri,
              w * along_h[cloth_springs.share_spring])
    area, tri_s, ring = _triangle_rings(mesh, x, edges)
    _, _, _, radius = shape.axial_coordinates(mesh, x)
    tri_r = radius[mesh.triangles].mean(axis=1)
    rows = []
    for k in range(len(edges) - 1):
        sel = ring == k
        if not sel.any():
            rows.append((float("nan"),) * 5)
            continue
        a = area[sel].sum()
        wrinkled = tri_hh[sel] < WRINKLED_HOOP_RATIO * tri_mm[sel]
        rows.append((float(tri_s[sel].mean()),
                     float((tri_r[sel] * area[sel]).sum() / a),
                     float(tri_mm[sel].sum() / a),
                     float(tri_hh[sel].sum() / a),
                     float(wrinkled.mean())))
    return rows


def ring_pressure_jump(mesh, x, dp, edges):
    """Per ring [edges[k], edges[k+1]) of the triangles' mean s, the
    area-weighted mean of the pressure jump dp (one value a triangle) [Pa];
    nan for an empty ring."""
    dp = np.asarray(dp, dtype=float)
    if dp.shape != (len(mesh.triangles),):
        raise ClothStressError("the pressure jump has %d values for %d "
                               "triangles" % (dp.size, len(mesh.triangles)))
    area, _, ring = _triangle_rings(mesh, x, edges)
    out = []
    for k in range(len(edges) - 1):
        sel = ring == k
        out.append(float((dp[sel] * area[sel]).sum() / area[sel].sum())
                   if sel.any() else float("nan"))
    return out, float((dp * area).sum() / area.sum())


def skirt_scallops(mesh, cloth_springs, x):
    """(attachments' mean radius, the largest skirt radius between them)
    of a state x, from the axis."""
    if len(cloth_springs.attachments) == 0:
        raise ClothStressError("no suspension line ends on the skirt")
    _, _, _, radius = shape.axial_coordinates(mesh, x)
    return (float(radius[cloth_springs.attachments].mean()),
            float(radius[mesh.skirt].max()))


def taut_hem_radius(r_attach, gores, hem_length):
    """The outermost radius of a taut hem of length hem_length between
    neighbouring attachments at radius r_attach of `gores` lines, bulging
    outward in the skirt's plane as a circular arc (module header)."""
    _, theta, rho = _hem_arc(r_attach, gores, hem_length)
    inner = r_attach * math.cos(math.pi / gores)
    if theta == 0.0:
        return inner
    return inner + rho * (1.0 - math.cos(theta))


def _hem_arc(r_attach, gores, hem_length):
    """(chord, half-angle theta, arc radius) of the taut hem between two
    attachments; theta 0 for a hem no longer than its chord."""
    if gores < 3 or not r_attach > 0 or not hem_length > 0:
        raise ValueError("a taut hem needs gores >= 3 and positive "
                         "lengths")
    chord = 2.0 * r_attach * math.sin(math.pi / gores)
    ratio = hem_length / chord
    if ratio <= 1.0:
        return chord, 0.0, math.inf
    lo, hi = 1e-9, math.pi - 1e-9
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if mid / math.sin(mid) < ratio:
            lo = mid
        else:
            hi = mid
    theta = 0.5 * (lo + hi)
    return chord, theta, chord / (2.0 * math.sin(theta))


def taut_hem_outline_diameter(r_attach, gores, hem_length):
    """The diameter of the circle of the same area as the skirt's outline:
    the polygon of the attachments plus the taut hem's circular segments
    between them, (gores / 2) r_a^2 sin(2 pi / gores) + gores rho^2
    (theta - sin theta cos theta)."""
    _, theta, rho = _hem_arc(r_attach, gores, hem_length)
    area = 0.5 * gores * r_attach ** 2 * math.sin(2.0 * math.pi / gores)
    if theta > 0.0:
        area += gores * rho ** 2 * (theta - math.sin(theta) *
                                    math.cos(theta))
    return 2.0 * math.sqrt(area / math.pi)


def read_states(case_dir, t0, t1):
    """(mesh, ClothSprings, [(time, x, tension, dp), ...]) of the states
    of canopy.h5 written in [t0, t1]; dp (the pressure jump a triangle) is
    None where the file does not hold it."""
    try:
        with canopy_h5.open_file(case_dir, ClothStressError) as f:
            m = f["mesh"]
            springs, groups = m["springs"][:], m["spring_group"][:]
            rest = m["spring_rest_length"][:]
            mesh = shape.CanopyMesh(m["node_group"][:], m["triangles"][:],
                                    springs, rest, groups)
            states = []
            for name in sorted(f["steps"].keys()):
                step = f["steps"][name]
                t = float(step.attrs["time"])
                if t0 - 1e-9 <= t <= t1 + 1e-9:
                    states.append((t, step["x"][:], step["tension"][:],
                                   step["dp"][:] if "dp" in step
                                   else None))
    except (OSError, KeyError) as e:
        raise ClothStressError("%s: %s" % (canopy_h5.path(case_dir), e))
    if not states:
        raise ClothStressError("canopy.h5 holds no state in t = %g .. %g s"
                               % (t0, t1))
    return mesh, ClothSprings(mesh, springs, groups, rest), states


def analyse(case_dir, t0, t1, rings=10):
    """The mean ring table and skirt over [t0, t1]: a dict with rows (s, r,
    sigma_mm, sigma_hh, wrinkled, dp), "pressureJump" the cloth's mean
    jump (dp and it nan where canopy.h5 holds no dp), the attachments' and
    the largest skirt
    radius, the taut hem's radius and outline diameter for the
    attachments' mean radius, the silhouette's diameter (shape.py), the
    gores, the lines' length, the rest radius R0 and the number of
    states; lengths in metres. "tensionField" holds tension-field
    theory's skirt (tension_field_shape.py, for the run's line length)
    and its taut hem's outline diameter."""
    from . import tension_field_shape
    mesh, cloth_springs, states = read_states(case_dir, t0, t1)
    edges = np.linspace(0.0, 1.0, rings + 1)
    tables, jumps = [], []
    for _, x, tension, dp in states:
        rows = ring_stress(mesh, cloth_springs, x, tension, edges)
        ring_dp, mean_dp = (ring_pressure_jump(mesh, x, dp, edges)
                            if dp is not None
                            else ([float("nan")] * rings, float("nan")))
        tables.append([row + (d,) for row, d in zip(rows, ring_dp)])
        jumps.append(mean_dp)
    tables = np.array(tables)
    scallops = np.array([skirt_scallops(mesh, cloth_springs, x)
                         for _, x, _, _ in states])
    silhouette = np.mean([shape.snapshot(mesh, x)["silhouetteDiameter"]
                          for _, x, _, _ in states])
    gores = len(cloth_springs.attachments)
    r_attach, r_largest = scallops.mean(axis=0)
    hem = cloth_springs.hem_length / gores
    r0 = mesh.rest_radius
    model = tension_field_shape.canopy(cloth_springs.line_length / r0)
    rows = []
    for k in range(rings):
        ring = tables[:, k, :]
        ring = ring[np.isfinite(ring[:, 0])]
        rows.append(tuple(float(v) for v in ring.mean(axis=0)) if len(ring)
                    else (float("nan"),) * 6)
    return {"rows": rows, "pressureJump": float(np.mean(jumps)),
            "attachmentRadius": float(r_attach),
            "largestSkirtRadius": float(r_largest),
            "tautHemRadius": taut_hem_radius(r_attach, gores, hem),
            "outlineDiameter": taut_hem_outline_diameter(r_attach, gores,
                                                         hem),
            "silhouetteDiameter": float(silhouette),
            "tensionField": {
                "skirtRadius": model["r_skirt"] * r0,
                "largestRadius": model["r_max"] * r0,
                "outlineDiameter": taut_hem_outline_diameter(
                    model["r_skirt"] * r0, gores, hem)},
            "gores": gores, "lineLength": cloth_springs.line_length,
            "restRadius": r0, "states": len(states)}


def main():
    if len(sys.argv) < 4:
        print(__doc__.split("\n")[0])
        print("usage: python3 -m canopyfoam.cloth_stress CASE T0 T1 [RINGS]")
        return 2
    try:
        case_dir, t0, t1 = sys.argv[1], float(sys.argv[2]), \
            float(sys.argv[3])
        rings = int(sys.argv[4]) if len(sys.argv) > 4 else 10
    except ValueError as e:
        print("cloth_stress: T0 and T1 are times in s, RINGS a whole "
              "number: %s" % e, file=sys.stderr)
        return 2
    if rings < 1:
        print("cloth_stress: RINGS must be at least 1", file=sys.stderr)
        return 2
    try:
        a = analyse(case_dir, t0, t1, rings)
    except (ClothStressError, shape.ShapeError) as e:
        print("cloth_stress: %s: %s" % (case_dir, e), file=sys.stderr)
        return 1
    r0 = a["restRadius"]
    print("%s over %g-%g s (%d states): the cloth's stress by ring of s "
          "(lengths in R0 = %.4g m, stresses in N/m)"
          % (case_dir, t0, t1, a["states"], r0))
    print("%6s %7s %9s %9s %9s %9s %9s %9s"
          % ("s", "r/R0", "sigma_mm", "sigma_hh", "r sig_mm", "wrinkled",
             "dp [Pa]", "dp/mean"))
    jump = a["pressureJump"]
    for s, r, smm, shh, wr, dp in a["rows"]:
        print("%6.3f %7.3f %9.2f %9.2f %9.2f %9.2f %9.2f %9.3f"
              % (s, r / r0, smm, shh, r * smm, wr, dp, dp / jump))
    print("the pressure jump across the cloth: %.2f Pa on the mean" % jump)
    d0 = 2.0 * r0
    tf = a["tensionField"]
    print("skirt: %d lines attached at r = %.3f R0, the largest radius "
          "between them %.3f R0; a taut hem arcing between the attachments "
          "reaches %.3f R0"
          % (a["gores"], a["attachmentRadius"] / r0,
             a["largestSkirtRadius"] / r0, a["tautHemRadius"] / r0))
    print("silhouette's diameter %.3f D0; the outline of the attachments "
          "and the taut hem, %.3f D0 (equal-area diameters)"
          % (a["silhouetteDiameter"] / d0, a["outlineDiameter"] / d0))
    print("tension-field theory (lines %.3f D0, axisymmetric): skirt at "
          "%.3f R0, widest %.3f R0 (Dp/D0); with a taut hem between its "
          "%d attachments the outline is %.3f D0"
          % (a["lineLength"] / d0, tf["skirtRadius"] / r0,
             tf["largestRadius"] / r0, a["gores"],
             tf["outlineDiameter"] / d0))
    return 0


if __name__ == "__main__":
    sys.exit(main())
