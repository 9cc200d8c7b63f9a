"""shape.py — the inflated canopy's shape from a run's canopy.h5: its profile (crown height, skirt and largest radius about the suspension axis) and its creases (the fold angle between neighbouring cloth triangles) by ring of the cloth.

Definitions (stated in bin/canopy-report's summary too):
- the axis points from the payload node to the mean of the cloth's nodes;
  heights are along it, radii are distances from it;
- the skirt is the cloth's longest boundary loop (by rest length); the crown
  height is the highest cloth node's height above the skirt nodes' mean;
- a cloth node's radial position s runs from 0 at the crown (the apex, or
  the vent's hem) to 1 at the skirt: 1 - d/d_max, d its shortest path to the
  skirt along the cloth's springs at their rest lengths;
- the silhouette is the cloth's projection on the plane normal to the axis
  (the union of its triangles' projections, sampled on a grid of
  SILHOUETTE_CELLS pixels across its larger extent at the pixels'
  centres); its diameter is that of the circle of equal area, the
  projected diameter of a canopy whose gores bulge between the lines
  (the largest radius is the bulges' tips);
- the fold angle of an edge shared by two triangles is the angle between
  their normals (0 on a smooth surface, 180 degrees where the cloth folds
  back on itself); an edge is folded when that angle exceeds 90 degrees.
  An edge belongs to the ring that holds the mean s of its two nodes.

Reading needs h5py (Debian's python3-h5py); the geometry is numpy only.
"""

import heapq
import math
import os
from collections import defaultdict

import numpy as np

from . import canopy_h5
from .canopy_h5 import GROUP_FABRIC, GROUP_TAPE, GROUP_PAYLOAD

RING_EDGES = (0.0, 0.3, 0.5, 0.7, 0.85, 1.0)
FOLDED_DEGREES = 90.0
SILHOUETTE_CELLS = 256


class ShapeError(Exception):
    pass


def edges_of(triangles):
    """{(i, j) with i < j: [triangle indices]} of a triangle list."""
    owners = defaultdict(list)
    for k, (a, b, c) in enumerate(np.asarray(triangles, dtype=int)):
        for i, j in ((a, b), (b, c), (c, a)):
            owners[(min(i, j), max(i, j))].append(k)
    return owners


def boundary_loops(owners):
    """The boundary's connected components (lists of edges used by one
    triangle), as lists of (i, j)."""
    boundary = [e for e, ts in owners.items() if len(ts) == 1]
    touching = defaultdict(list)
    for e in boundary:
        touching[e[0]].append(e)
        touching[e[1]].append(e)
    seen, loops = set(), []
    for start in boundary:
        if start in seen:
            continue
        loop, todo = [], [start]
        seen.add(start)
        while todo:
            e = todo.pop()
            loop.append(e)
            for n in e:
                for f in touching[n]:
                    if f not in seen:
                        seen.add(f)
                        todo.append(f)
        loops.append(loop)
    return loops


def radial_position(n_nodes, springs, rest_lengths, skirt_nodes, cloth):
    """(s, d_max): s per node (NaN off the cloth) is 1 - d/d_max, d the
    shortest path to the skirt over the given springs at their rest
    lengths; d_max, the longest, is the cloth's radius at rest."""
    adjacency = defaultdict(list)
    for (i, j), l0 in zip(np.asarray(springs, dtype=int), rest_lengths):
        if cloth[i] and cloth[j]:
            adjacency[i].append((j, float(l0)))
            adjacency[j].append((i, float(l0)))
    d = np.full(n_nodes, np.inf)
    heap = []
    for n in skirt_nodes:
        d[n] = 0.0
        heap.append((0.0, n))
    heapq.heapify(heap)
    while heap:
        dn, n = heapq.heappop(heap)
        if dn > d[n]:
            continue
        for m, l0 in adjacency[n]:
            if dn + l0 < d[m]:
                d[m] = dn + l0
                heapq.heappush(heap, (d[m], m))
    s = np.full(n_nodes, np.nan)
    reached = cloth & np.isfinite(d)
    dmax = d[reached].max() if reached.any() else 0.0
    if dmax <= 0.0:
        raise ShapeError("the cloth has no node away from its skirt")
    s[reached] = 1.0 - d[reached] / dmax
    return s, float(dmax)


class CanopyMesh(object):
    """What the shape needs of the canopy's mesh: the cloth's triangles,
    its interior edges with their ring, the skirt's nodes and the payload
    node."""

    def __init__(self, groups, triangles, springs, rest_lengths,
                 spring_groups, ring_edges=RING_EDGES):
        groups = np.asarray(groups, dtype=int)
        self.triangles = np.asarray(triangles, dtype=int)
        if len(self.triangles) == 0:
            raise ShapeError("the mesh has no cloth triangles")
        payload = np.where(groups == GROUP_PAYLOAD)[0]
        if len(payload) == 0:
            raise ShapeError("the mesh has no payload node (group %d): the "
                             "shape's axis needs one" % GROUP_PAYLOAD)
        self.payload = int(payload[0])
        self.cloth = np.isin(groups, (GROUP_FABRIC, GROUP_TAPE))
        self.cloth_nodes = np.unique(self.triangles)
        owners = edges_of(self.triangles)
        loops = boundary_loops(owners)
        if not loops:
            raise ShapeError("the cloth has no boundary (no skirt)")
        springs = np.asarray(springs, dtype=int)
        rest = dict(((min(i, j), max(i, j)), l0) for (i, j), l0 in
                    zip(springs, rest_lengths))
        cloth_springs = np.isin(np.asarray(spring_groups, dtype=int),
                                (GROUP_FABRIC, GROUP_TAPE))

        def loop_length(loop):
            return sum(rest.get(e, 0.0) for e in loop)
        skirt = max(loops, key=loop_length)
        self.skirt = np.array(sorted(set(n for e in skirt for n in e)))
        self.s, self.rest_radius = radial_position(
            len(groups), springs[cloth_springs],
            np.asarray(rest_lengths)[cloth_springs], self.skirt, self.cloth)
        interior = [(e, ts) for e, ts in owners.items() if len(ts) == 2]
        self.edge_triangles = np.array([ts for _, ts in interior], dtype=int)\
            .reshape(-1, 2)
        edge_nodes = np.array([e for e, _ in interior], dtype=int)\
            .reshape(-1, 2)
        self.edge_s = self.s[edge_nodes].mean(axis=1) if len(interior) \
            else np.zeros(0)
        self.ring_edges = tuple(ring_edges)
        self.edge_ring = np.clip(np.searchsorted(self.ring_edges,
                                                 self.edge_s, side="right")
                                 - 1, 0, len(self.ring_edges) - 2)


def triangle_normals(x, triangles):
    n = np.cross(x[triangles[:, 1]] - x[triangles[:, 0]],
                 x[triangles[:, 2]] - x[triangles[:, 0]])
    norm = np.linalg.norm(n, axis=1)
    return n / np.where(norm > 0.0, norm, 1.0)[:, None]


def silhouette_area(points, triangles, cells=SILHOUETTE_CELLS):
    """The area of the union of the 2-D triangles (points: n x 2), counted
    on a grid of `cells` pixels across the larger extent at the pixels'
    centres: off by at most half a pixel's width times the outline's
    length."""
    p = np.asarray(points, dtype=float)
    tri = np.asarray(triangles, dtype=int)
    used = p[np.unique(tri)]
    lo, hi = used.min(axis=0), used.max(axis=0)
    h = max(hi[0] - lo[0], hi[1] - lo[1]) / cells
    if h <= 0.0:
        return 0.0
    shape = (int(math.ceil((hi[0] - lo[0]) / h)) + 1,
             int(math.ceil((hi[1] - lo[1]) / h)) + 1)
    covered = np.zeros(shape, dtype=bool)
    for a, b, c in tri:
        A, B, C = p[a], p[b], p[c]
        det = (B[0] - A[0]) * (C[1] - A[1]) - (C[0] - A[0]) * (B[1] - A[1])
        if det == 0.0:
            continue
        tlo = np.floor((np.minimum(np.minimum(A, B), C) - lo) / h - 0.5)
        thi = np.ceil((np.maximum(np.maximum(A, B), C) - lo) / h - 0.5)
        i0, j0 = max(int(tlo[0]), 0), max(int(tlo[1]), 0)
        i1 = min(int(thi[0]), shape[0] - 1)
        j1 = min(int(thi[1]), shape[1] - 1)
        if i1 < i0 or j1 < j0:
            continue
        X, Y = np.meshgrid(lo[0] + (np.arange(i0, i1 + 1) + 0.5) * h,
                           lo[1] + (np.arange(j0, j1 + 1) + 0.5) * h,
                           indexing="ij")
        u = ((X - A[0]) * (C[1] - A[1]) - (C[0] - A[0]) * (Y - A[1])) / det
        v = ((B[0] - A[0]) * (Y - A[1]) - (X - A[0]) * (B[1] - A[1])) / det
        inside = (u >= 0.0) & (v >= 0.0) & (u + v <= 1.0)
        covered[i0:i1 + 1, j0:j1 + 1] |= inside
    return float(covered.sum()) * h * h


def axial_coordinates(mesh, x):
    """(axis, rel, height, radius) of a state x (nodes x 3): the unit axis
    from the payload to the cloth's mean, each node's position relative to
    that mean, its height along the axis and its distance from it."""
    x = np.asarray(x, dtype=float)
    centre = x[mesh.cloth_nodes].mean(axis=0)
    axis = centre - x[mesh.payload]
    length = np.linalg.norm(axis)
    if length == 0.0:
        raise ShapeError("the payload is at the cloth's centre: no axis")
    axis /= length
    rel = x - centre
    height = rel @ axis
    return axis, rel, height, np.linalg.norm(rel - np.outer(height, axis),
                                             axis=1)


def snapshot(mesh, x):
    """The shape of one state x (nodes x 3) of `mesh`: a dict."""
    x = np.asarray(x, dtype=float)
    axis, rel, height, radius = axial_coordinates(mesh, x)
    skirt_h = height[mesh.skirt].mean()
    e1 = np.cross(axis, [1.0, 0.0, 0.0])
    if np.linalg.norm(e1) < 0.5:
        e1 = np.cross(axis, [0.0, 1.0, 0.0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(axis, e1)
    area = silhouette_area(np.column_stack((rel @ e1, rel @ e2)),
                           mesh.triangles)
    n = triangle_normals(x, mesh.triangles)
    cosang = np.einsum("ij,ij->i", n[mesh.edge_triangles[:, 0]],
                       n[mesh.edge_triangles[:, 1]])
    fold = np.degrees(np.arccos(np.clip(cosang, -1.0, 1.0)))
    rings = []
    for k in range(len(mesh.ring_edges) - 1):
        m = mesh.edge_ring == k
        rings.append({
            "inner": mesh.ring_edges[k], "outer": mesh.ring_edges[k + 1],
            "edges": int(m.sum()),
            "foldMean": float(fold[m].mean()) if m.any() else float("nan"),
            "foldedFraction": float((fold[m] > FOLDED_DEGREES).mean())
            if m.any() else float("nan")})
    return {
        "crownHeight": float(height[mesh.cloth_nodes].max() - skirt_h),
        "skirtRadiusMean": float(radius[mesh.skirt].mean()),
        "skirtRadiusMin": float(radius[mesh.skirt].min()),
        "skirtRadiusMax": float(radius[mesh.skirt].max()),
        "largestRadius": float(radius[mesh.cloth_nodes].max()),
        "silhouetteDiameter": math.sqrt(4.0 * area / math.pi),
        "foldedFraction": float((fold > FOLDED_DEGREES).mean())
        if len(fold) else float("nan"),
        "rings": rings,
    }


def mean_shape(snapshots):
    """The plain mean of snapshots' numbers (snapshots are written at a
    fixed interval)."""
    keys = ("crownHeight", "skirtRadiusMean", "skirtRadiusMin",
            "skirtRadiusMax", "largestRadius", "silhouetteDiameter",
            "foldedFraction")
    out = {k: float(np.mean([s[k] for s in snapshots])) for k in keys}
    out["rings"] = []
    for k, ring in enumerate(snapshots[0]["rings"]):
        out["rings"].append(dict(ring, **{
            q: float(np.mean([s["rings"][k][q] for s in snapshots]))
            for q in ("foldMean", "foldedFraction")}))
    return out


h5_path = canopy_h5.path


def read_case(case_dir, t0=-math.inf, t1=math.inf):
    """(mesh, [(time, x), ...]) from <case>/postProcessing/canopy/canopy.h5,
    the states written in [t0, t1] (none: ShapeError)."""
    path = h5_path(case_dir)
    try:
        with canopy_h5.open_file(case_dir, ShapeError) as f:
            m = f["mesh"]
            mesh = CanopyMesh(m["node_group"][:], m["triangles"][:],
                              m["springs"][:], m["spring_rest_length"][:],
                              m["spring_group"][:])
            states = []
            for name in sorted(f["steps"].keys()):
                step = f["steps"][name]
                t = float(step.attrs["time"])
                if t0 - 1e-9 <= t <= t1 + 1e-9:
                    states.append((t, step["x"][:]))
    except (OSError, KeyError) as e:
        raise ShapeError("%s: %s" % (os.path.relpath(path, case_dir), e))
    if not states:
        raise ShapeError("canopy.h5 holds no state in t = %g .. %g s"
                         % (t0, t1))
    return mesh, states


def analyse(case_dir, t0, t1):
    """The mean shape (mean_shape) over the states written in [t0, t1], with
    their number and first and last times; lengths in metres."""
    mesh, states = read_case(case_dir, t0, t1)
    out = mean_shape([snapshot(mesh, x) for _, x in states])
    out.update(states=len(states), timeFirst=states[0][0],
               timeLast=states[-1][0])
    return out
