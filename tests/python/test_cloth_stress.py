"""test_cloth_stress.py — known-answer tests of python/canopyfoam/cloth_stress.py (the cloth's meridional and hoop stress by ring, the skirt's scallops, the taut hem's arc) on synthetic polar meshes.

Run as:  /usr/bin/python3 tests/python/test_cloth_stress.py   (./Alltest cloth_stress)
Prints one PASS/FAIL line per check with the numbers; exits 1 if any fails.

The cloth is test_shape.py's polar mesh (radius R = 1 m, a centre node and
N = 10 rings of M = 16 nodes, ring i at radius r_i = i R / N; spokes, ring
chords and one diagonal per quad), the payload 3 m below the centre and a
line from every other skirt node to it (8 attachments). With the rings of
s at k / N each annulus i holds exactly its own triangles, of area
A_i = (M / 2) sin(2 pi / M) (r_{i+1}^2 - r_i^2), and
  spokes alone at tension T:  a spoke lies along the meridian at its
      midpoint, so sigma_hh = 0 and sigma_mm = M T (R / N) / A_i (both its
      triangles lie in annulus i); every triangle is wrinkled;
  ring chords alone at T:     a chord lies along the hoop at its midpoint,
      so sigma_mm = 0 and sigma_hh = M T (c_i / 2 + c_{i+1} w) / A_i,
      c_k = 2 r_k sin(pi / M) (ring 0 has none), w = 1/2 but 1 for the
      skirt's chords, which have one triangle;
  the same rotated and moved in space: the same numbers;
  the disc wrapped on a sphere of radius 1.5 m keeping the spokes' length,
      spokes at T: a spoke and the mean normal of its two triangles lie in
      its meridian plane, so sigma_hh = 0 and sigma_mm = M T l_i / A_i, l_i
      the spoke's chord and A_i the annulus's triangles' area.
All to 1e-12 relative (sums of a few hundred terms). The taut hem:
a semicircle (L = pi c / 2) bulges by c / 2 beyond the chord's midpoint
r_a cos(pi / N), a hem as long as its chord by nothing, and the
outline's area is the attachments' polygon plus N half discs of
diameter c, or the polygon alone; to 1e-9 (the bisection's tolerance). The scallops: the attachments at R and the other
skirt nodes moved out to 1.2 R read 1 and 1.2. The pressure jump: annulus
i's triangles at 10 i + 1 (a quad's outer triangle, area proportional to
r_{i+1}, and the centre's fan) and 10 i + 3 (the inner, to r_i) give
the ring means 10 i + (r_{i+1} + 3 r_i) / (r_{i+1} + r_i) and the cloth's
their annulus-weighted mean, to 1e-12; a wrong count is refused. Through canopy.h5 (h5py):
two states averaged (the pressure jump's columns too), the hem's rest length M c_N, the taut hem's
radius and outline for 8 gores, the lines' length sqrt(R^2 + 3^2) and
the silhouette's diameter as shape.py gives it; a cloth without lines is refused by name.
"""

import math
import os
import shutil
import tempfile

import numpy as np

from checks import check, finish, refused, write_canopy_h5
from canopyfoam import cloth_stress, shape, tension_field_shape
from canopyfoam.canopy_h5 import GROUP_LINE, GROUP_PAYLOAD

N, M, R = 10, 16, 1.0
T = 2.0


def polar_mesh():
    """(positions, node groups, triangles, springs, rest lengths, spring
    groups, ring per node, kind per spring: 's' spoke, 'c' chord, 'd'
    diagonal, 'l' line)."""
    pts, ring = [(0.0, 0.0, 0.0)], [0]
    for i in range(1, N + 1):
        for j in range(M):
            a = 2 * math.pi * j / M
            pts.append((i * R / N * math.cos(a), i * R / N * math.sin(a),
                        0.0))
            ring.append(i)

    def node(i, j):
        return 0 if i == 0 else 1 + (i - 1) * M + j % M
    tris = [(0, node(1, j), node(1, j + 1)) for j in range(M)]
    for i in range(1, N):
        for j in range(M):
            tris.append((node(i, j), node(i + 1, j), node(i + 1, j + 1)))
            tris.append((node(i, j), node(i + 1, j + 1), node(i, j + 1)))
    payload = len(pts)
    pts.append((0.0, 0.0, -3.0))
    ring.append(-1)
    x = np.array(pts)
    ring = np.array(ring)
    groups = np.zeros(len(pts), dtype=int)
    groups[payload] = GROUP_PAYLOAD
    edges = sorted(shape.edges_of(tris))
    kinds = []
    for a, b in edges:
        if ring[a] == ring[b]:
            kinds.append("c")
        elif a == 0 or (a - 1) % M == (b - 1) % M:
            kinds.append("s")
        else:
            kinds.append("d")
    lines = [(node(N, j), payload) for j in range(0, M, 2)]
    springs = np.array(edges + lines)
    kinds += ["l"] * len(lines)
    sgroups = np.array([GROUP_LINE if k == "l" else 0 for k in kinds])
    rest = np.linalg.norm(x[springs[:, 0]] - x[springs[:, 1]], axis=1)
    return (x, groups, np.array(tris), springs, rest, sgroups, ring,
            np.array(kinds))


x0, groups, tris, springs, rest, sgroups, ring, kinds = polar_mesh()
mesh = shape.CanopyMesh(groups, tris, springs, rest, sgroups)
cs = cloth_stress.ClothSprings(mesh, springs, sgroups, rest)
edges = np.arange(N + 1) / float(N)
r = np.arange(N + 1) * R / N
annulus = 0.5 * M * math.sin(2 * math.pi / M) * (r[1:] ** 2 - r[:-1] ** 2)
chord = 2 * r * math.sin(math.pi / M)
spokes = np.where(kinds == "s", T, 0.0)
chords = np.where(kinds == "c", T, 0.0)


def worst(rows, column, exact):
    got = np.array([row[column] for row in rows])
    scale = np.max(np.abs(exact)) if np.max(np.abs(exact)) > 0 else 1.0
    return float(np.max(np.abs(got - exact)) / scale)


check("springs", len(cs.spring) == int((kinds != "l").sum())
      and len(cs.attachments) == M // 2,
      "%d cloth springs on triangles, %d attachments"
      % (len(cs.spring), len(cs.attachments)))

rows = cloth_stress.ring_stress(mesh, cs, x0, spokes, edges)
mm = M * T * (R / N) / annulus
e_mm, e_hh = worst(rows, 2, mm), worst(rows, 3, np.zeros(N))
wr = min(row[4] for row in rows)
check("flat, spokes: sigma_mm = M T dr / A_i, sigma_hh = 0, all wrinkled",
      e_mm < 1e-12 and e_hh < 1e-12 and wr == 1.0,
      "sigma_mm %.6f .. %.6f N/m, relative error %.2g; sigma_hh error %.2g "
      "(tolerance 1e-12); smallest wrinkled fraction %g"
      % (mm.min(), mm.max(), e_mm, e_hh, wr))

rows = cloth_stress.ring_stress(mesh, cs, x0, chords, edges)
hh = M * T * (0.5 * chord[:-1] + np.where(np.arange(N) == N - 1, 1.0, 0.5)
              * chord[1:]) / annulus
e_mm, e_hh = worst(rows, 2, np.zeros(N)), worst(rows, 3, hh)
wr = max(row[4] for row in rows)
check("flat, chords: sigma_hh exact, sigma_mm = 0, none wrinkled",
      e_mm < 1e-12 and e_hh < 1e-12 and wr == 0.0,
      "sigma_hh %.6f .. %.6f N/m, relative error %.2g; sigma_mm error %.2g "
      "(tolerance 1e-12); largest wrinkled fraction %g"
      % (hh.min(), hh.max(), e_hh, e_mm, wr))

c, s = math.cos(0.7), math.sin(0.7)
rot = np.array([[1, 0, 0], [0, c, -s], [0, s, c]]) @ \
    np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])
moved = x0 @ rot.T + np.array([3.0, -2.0, 5.0])
rows = cloth_stress.ring_stress(mesh, cs, moved, spokes + chords, edges)
e_mm, e_hh = worst(rows, 2, mm), worst(rows, 3, hh)
check("rotated and moved, spokes and chords: the same stresses",
      e_mm < 1e-12 and e_hh < 1e-12,
      "relative errors sigma_mm %.2g, sigma_hh %.2g (tolerance 1e-12)"
      % (e_mm, e_hh))

rho = 1.5
cloth = ring >= 0
r0 = np.hypot(x0[:, 0], x0[:, 1])
phi = np.arctan2(x0[:, 1], x0[:, 0])
cap = x0.copy()
th = r0[cloth] / rho
cap[cloth] = np.column_stack([rho * np.sin(th) * np.cos(phi[cloth]),
                              rho * np.sin(th) * np.sin(phi[cloth]),
                              rho * np.cos(th) - rho])
tx = cap[tris]
area = 0.5 * np.linalg.norm(np.cross(tx[:, 1] - tx[:, 0], tx[:, 2] - tx[:, 0]),
                            axis=1)
tri_ring = np.floor(mesh.s[tris].mean(axis=1) * N).astype(int)
cap_area = np.array([area[tri_ring == i].sum() for i in range(N)])
spoke_chord = 2 * rho * math.sin(R / N / (2 * rho))
rows = cloth_stress.ring_stress(mesh, cs, cap, spokes, edges)
cap_mm = M * T * spoke_chord / cap_area
e_mm, e_hh = worst(rows, 2, cap_mm), worst(rows, 3, np.zeros(N))
check("spherical cap, spokes: sigma_mm = M T l / A_i, sigma_hh = 0",
      e_mm < 1e-12 and e_hh < 1e-12,
      "sigma_mm %.6f .. %.6f N/m, relative error %.2g; sigma_hh error %.2g "
      "(tolerance 1e-12)" % (cap_mm.min(), cap_mm.max(), e_mm, e_hh))

# the pressure jump by ring: annulus i's triangles carry 10 i + 1 (the
# outer of each quad, area (dr/2) r_{i+1} sin(2 pi/M), and the centre's
# fan) and 10 i + 3 (the inner, area (dr/2) r_i sin(2 pi/M))
k = np.arange(len(tris))
tri_ring = np.where(k < M, 0, 1 + (k - M) // (2 * M))
outer = (k < M) | ((k - M) % 2 == 0)
dp = 10.0 * tri_ring + np.where(outer, 1.0, 3.0)
exact = 10.0 * np.arange(N) + (r[1:] + 3 * r[:-1]) / (r[1:] + r[:-1])
exact_mean = float((exact * annulus).sum() / annulus.sum())
got, mean = cloth_stress.ring_pressure_jump(mesh, x0, dp, edges)
e_dp = float(np.max(np.abs(np.array(got) - exact)) / exact.max())
check("pressure jump: area-weighted ring means and the cloth's mean",
      e_dp < 1e-12 and abs(mean / exact_mean - 1) < 1e-12,
      "rings %.6f .. %.6f Pa, relative error %.2g; mean %.12f Pa (exact "
      "%.12f; tolerance 1e-12)" % (exact.min(), exact.max(), e_dp, mean,
                                   exact_mean))
refused("pressure jump: a value a triangle or refused",
        lambda: cloth_stress.ring_pressure_jump(mesh, x0, dp[:-1], edges),
        cloth_stress.ClothStressError, "triangles")

# the taut hem
ra, gores = 0.7, 16
c16 = 2 * ra * math.sin(math.pi / gores)
inner = ra * math.cos(math.pi / gores)
semi = cloth_stress.taut_hem_radius(ra, gores, math.pi * c16 / 2)
straight = cloth_stress.taut_hem_radius(ra, gores, c16)
check("taut hem: a semicircle bulges by half its chord, a straight hem not",
      abs(semi - (inner + c16 / 2)) < 1e-9 and abs(straight - inner) < 1e-12,
      "semicircle %.12f (exact %.12f), straight %.12f (exact %.12f)"
      % (semi, inner + c16 / 2, straight, inner))
polygon = 0.5 * gores * ra ** 2 * math.sin(2 * math.pi / gores)
semi_d = cloth_stress.taut_hem_outline_diameter(ra, gores,
                                                math.pi * c16 / 2)
exact_semi = 2 * math.sqrt((polygon + gores * math.pi * c16 ** 2 / 8)
                           / math.pi)
straight_d = cloth_stress.taut_hem_outline_diameter(ra, gores, c16)
exact_straight = 2 * math.sqrt(polygon / math.pi)
check("taut hem's outline: the polygon plus semicircles, the polygon alone",
      abs(semi_d - exact_semi) < 1e-9 and
      abs(straight_d - exact_straight) < 1e-12,
      "semicircles %.12f m (exact %.12f), straight %.12f m (exact %.12f)"
      % (semi_d, exact_semi, straight_d, exact_straight))
refused("taut hem: two gores refused",
        lambda: cloth_stress.taut_hem_radius(ra, 2, 1.0), ValueError, "gores")

# the scallops
scallop = x0.copy()
outer = (ring == N) & ~np.isin(np.arange(len(ring)), cs.attachments)
scallop[outer, :2] *= 1.2
att, largest = cloth_stress.skirt_scallops(mesh, cs, scallop)
check("scallops: attachments at R, the hem between at 1.2 R",
      abs(att - R) < 1e-12 and abs(largest - 1.2 * R) < 1e-12,
      "attachments %.15g m, largest %.15g m" % (att, largest))
no_lines = cloth_stress.ClothSprings(mesh, springs, np.zeros(len(springs)),
                                     rest)
refused("scallops: a cloth without lines refused",
        lambda: cloth_stress.skirt_scallops(mesh, no_lines, x0),
        cloth_stress.ClothStressError, "line")

# through canopy.h5
try:
    import h5py
except ImportError:
    h5py = None
check("h5py available", h5py is not None,
      "python3-h5py (bin/setup installs it)")
if h5py is not None:
    tmp = tempfile.mkdtemp(prefix="test_cloth_stress.")
    try:
        os.makedirs(os.path.join(tmp, "postProcessing", "canopy"))
        # t = 1: spokes at T; t = 2: spokes at 3 T; t = 3: outside
        write_canopy_h5(shape.h5_path(tmp), groups, tris, springs, rest,
                        sgroups, [(t, {"x": x0, "tension": tension,
                                       "dp": dp})
                                  for t, tension in ((1.0, spokes),
                                                     (2.0, 3 * spokes),
                                                     (3.0, 10 * spokes))])
        a = cloth_stress.analyse(tmp, 0.5, 2.5, N)
        e_mm = worst(a["rows"], 2, 2 * mm)
        hem = M * chord[N]
        taut = cloth_stress.taut_hem_radius(R, M // 2, hem / (M // 2))
        outline = cloth_stress.taut_hem_outline_diameter(R, M // 2,
                                                         hem / (M // 2))
        check("h5: two states averaged, the hem and its taut radius",
              a["states"] == 2 and e_mm < 1e-12 and a["gores"] == M // 2
              and abs(a["attachmentRadius"] - R) < 1e-12
              and abs(a["tautHemRadius"] - taut) < 1e-12
              and abs(a["outlineDiameter"] - outline) < 1e-12
              and abs(a["pressureJump"] / exact_mean - 1) < 1e-12
              and worst(a["rows"], 5, exact) < 1e-12,
              "%d states, sigma_mm error %.2g against the mean 2 T; %d "
              "gores, hem %.6f m, taut hem radius %.6f m, outline %.6f m; "
              "pressure jump %.6f Pa"
              % (a["states"], e_mm, a["gores"], hem, a["tautHemRadius"],
                 a["outlineDiameter"], a["pressureJump"]))
        line = math.sqrt(R ** 2 + 3.0 ** 2)
        model = tension_field_shape.canopy(line / R)
        flat = shape.snapshot(mesh, x0)["silhouetteDiameter"]
        check("h5: the lines' length, tension-field theory's skirt, the "
              "silhouette",
              abs(a["lineLength"] - line) < 1e-12 and
              abs(a["tensionField"]["skirtRadius"] - model["r_skirt"] * R)
              < 1e-12 and abs(a["silhouetteDiameter"] - flat) < 1e-12,
              "lines %.12f m (exact %.12f), skirt %.6f m, silhouette %.6f m"
              % (a["lineLength"], line, a["tensionField"]["skirtRadius"],
                 a["silhouetteDiameter"]))
        refused("h5: empty interval refused",
                lambda: cloth_stress.analyse(tmp, 5.0, 6.0),
                cloth_stress.ClothStressError, "no state")
    finally:
        shutil.rmtree(tmp)

finish()
