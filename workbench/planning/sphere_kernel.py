"""Compiled (numba) sphere-model collision checks of one configuration or one straight motion.

The same checks as :meth:`workbench.planning.spheres.SphereChecker.configs_free_reference`
(the numpy version), in one compiled loop that stops at the first collision:

1. forward kinematics of the group's moving frames (3x4 poses, one Rodrigues
   step per joint);
2. every moving body against the obstacles, down the bounding-sphere
   hierarchy of :mod:`workbench.planning.sphere_layout` (body, cluster,
   sphere), each level cleared by the obstacles' distance table or tested
   against the obstacle primitives (spheres, boxes, cylinders);
3. self-collision of the body pairs that need it, down the same hierarchy;
   a pair whose exact distance table clears it is skipped.

Every comparison is made with the radii grown by :data:`EPS`, so the kernel
never accepts a configuration the numpy version rejects because of a
different rounding order; it may reject a few more (within a nanometre of
contact). All arrays are packed once per checker by
:meth:`~workbench.planning.spheres.SphereChecker.kernel_data`, in the order of
:data:`FIELDS`, and packed into a few buffers by :func:`pack`.
"""

from __future__ import annotations

import math

import numpy as np

from workbench.optional import require

njit = require("numba").njit

#: Growth of every radius in the compiled comparisons, m.
EPS = 1e-9

#: The model's arrays, in the order the kernels unpack them: (name, buffer, ndim). Buffer
#: "f" is the float64 buffer, "i" the int64 one (bools as 0/1), "t" the float32 table.
FIELDS = (
    ("step_child", "i", 1),  # (J,) int64: slot a group joint moves
    ("step_parent", "i", 1),  # (J,) int64: its parent's slot (0 = world)
    ("step_joint", "i", 1),  # (J,) int64: the joint's index in the group vector
    ("step_stack", "f", 4),  # (J, 3, 4, 4) float64: X_PC(q) = M0 + c1 M1 + c2 M2
    ("prismatic", "i", 1),  # (n,) bool as 0/1
    ("local", "f", 2),  # (S, 3) sphere centres in their slot's frame, m
    ("radii", "f", 1),  # (S,) float64, m (padding included)
    ("cl_slot", "i", 1),  # (C,) int64 slot of each cluster
    ("cl_local", "f", 2),  # (C, 3) cluster bounding-sphere centres in the slot frame
    ("cl_r", "f", 1),  # (C,) their radii
    ("cl_span", "i", 2),  # (C, 2) int64 the cluster's spheres [start, end)
    ("part_slot", "i", 1),  # (P,) int64 slot of each body part
    ("part_local", "f", 2),  # (P, 3) body bounding-sphere centres in the slot frame
    ("part_r", "f", 1),  # (P,) their radii
    ("part_span", "i", 2),  # (P, 2) int64 the part's clusters [start, end)
    ("env_parts", "i", 1),  # (E,) int64 parts checked against the obstacles
    ("has_field", "i", 1),  # (1,) bool as 0/1: the obstacles' distance table exists
    ("field", "t", 3),  # (X, Y, Z) float32 distance table, m
    ("field_lo", "f", 1),  # (3,) its lower corner, m
    ("field_spec", "f", 1),  # (2,) spacing and slack (half the cell diagonal), m
    ("obs_sphere_c", "f", 2),  # (Ks, 3) obstacle spheres
    ("obs_sphere_r", "f", 1),  # (Ks,)
    ("box_R", "f", 3),  # (Kb, 3, 3) box rotations (world from box)
    ("box_off", "f", 2),  # (Kb, 3) p @ R
    ("box_h", "f", 2),  # (Kb, 3) half sizes
    ("cyl_R", "f", 3),  # (Kc, 3, 3)
    ("cyl_off", "f", 2),  # (Kc, 3)
    ("cyl_rh", "f", 2),  # (Kc, 2) radius and half length
    ("grid_joints", "i", 2),  # (G, 2) int64 group indices of a table's axes (-1 = unused)
    ("grid_origin", "f", 2),  # (G, 2) first value of each axis
    ("grid_shape", "i", 2),  # (G, 2) int64 axis lengths (1 when unused)
    ("grid_spec", "f", 2),  # (G, 2) step and margin
    ("grid_offset", "i", 1),  # (G,) int64 start of each table in grid_table
    ("grid_table", "f", 1),  # (sum,) float64 tables, row-major, concatenated
    ("pair_parts", "i", 2),  # (K, 2) int64 body part pairs checked for self-collision
    ("pair_reach2", "f", 1),  # (K,) (bounding radii sum + EPS)^2
    ("pair_grid", "i", 1),  # (K,) int64 the pair's distance table, -1 for none
)

# _config_free slices the model tuple at these fields
assert [f[0] for f in FIELDS].index("has_field") == 16
assert [f[0] for f in FIELDS].index("grid_joints") == 28


@njit(cache=True, nogil=True, inline="always")
def _view1(buf, meta, k):
    o = meta[k, 0]
    return buf[o : o + meta[k, 1]]


@njit(cache=True, nogil=True, inline="always")
def _view2(buf, meta, k):
    o = meta[k, 0]
    return buf[o : o + meta[k, 1] * meta[k, 2]].reshape((meta[k, 1], meta[k, 2]))


@njit(cache=True, nogil=True, inline="always")
def _view3(buf, meta, k):
    o, a, b, c = meta[k, 0], meta[k, 1], meta[k, 2], meta[k, 3]
    return buf[o : o + a * b * c].reshape((a, b, c))


@njit(cache=True, nogil=True, inline="always")
def _view4(buf, meta, k):
    o, a, b, c, d = meta[k, 0], meta[k, 1], meta[k, 2], meta[k, 3], meta[k, 4]
    return buf[o : o + a * b * c * d].reshape((a, b, c, d))


@njit(cache=True, nogil=True)
def _unpack(fbuf, ibuf, table, meta):
    """The model's arrays (:data:`FIELDS`) as views into the packed buffers."""
    return (
        _view1(ibuf, meta, 0),
        _view1(ibuf, meta, 1),
        _view1(ibuf, meta, 2),
        _view4(fbuf, meta, 3),
        _view1(ibuf, meta, 4),
        _view2(fbuf, meta, 5),
        _view1(fbuf, meta, 6),
        _view1(ibuf, meta, 7),
        _view2(fbuf, meta, 8),
        _view1(fbuf, meta, 9),
        _view2(ibuf, meta, 10),
        _view1(ibuf, meta, 11),
        _view2(fbuf, meta, 12),
        _view1(fbuf, meta, 13),
        _view2(ibuf, meta, 14),
        _view1(ibuf, meta, 15),
        _view1(ibuf, meta, 16),
        table,
        _view1(fbuf, meta, 18),
        _view1(fbuf, meta, 19),
        _view2(fbuf, meta, 20),
        _view1(fbuf, meta, 21),
        _view3(fbuf, meta, 22),
        _view2(fbuf, meta, 23),
        _view2(fbuf, meta, 24),
        _view3(fbuf, meta, 25),
        _view2(fbuf, meta, 26),
        _view2(fbuf, meta, 27),
        _view2(ibuf, meta, 28),
        _view2(fbuf, meta, 29),
        _view2(ibuf, meta, 30),
        _view2(fbuf, meta, 31),
        _view1(ibuf, meta, 32),
        _view1(fbuf, meta, 33),
        _view2(ibuf, meta, 34),
        _view1(fbuf, meta, 35),
        _view1(ibuf, meta, 36),
    )


@njit(cache=True, nogil=True)
def _work_views(fwork, iwork, meta):
    """Work arrays in the work buffers: poses, centres of spheres, clusters and parts, and
    the tick at which each cluster, cluster's spheres and part was last computed."""
    S, C, P = meta[5, 1], meta[7, 1], meta[11, 1]
    slots = (len(fwork) - 3 * (S + C + P)) // 12
    X = fwork[: slots * 12].reshape((slots, 3, 4))
    o = slots * 12
    Cs = fwork[o : o + 3 * S].reshape((S, 3))
    o += 3 * S
    CC = fwork[o : o + 3 * C].reshape((C, 3))
    o += 3 * C
    PC = fwork[o : o + 3 * P].reshape((P, 3))
    return X, Cs, CC, PC, iwork[:C], iwork[C : 2 * C], iwork[2 * C : 2 * C + P], iwork[-1:]


def pack(arrays: tuple, slots: int) -> tuple:
    """Pack the model's arrays (in :data:`FIELDS` order) into the buffers the kernels take.

    Returns:
        ``(fbuf, ibuf, table, meta, fwork, iwork)``: pass them after the configuration(s)
        to :func:`configs_free`, :func:`config_free` and :func:`motion_status`. Few
        arguments keep each call from Python cheap (numba types every argument).
    """
    floats, ints, meta, table = [], [], np.zeros((len(FIELDS), 5), dtype=np.int64), None
    offsets = {"f": 0, "i": 0}
    for k, ((name, kind, ndim), array) in enumerate(zip(FIELDS, arrays, strict=True)):
        array = np.asarray(array)
        if array.ndim != ndim:
            raise ValueError(f"sphere kernel field {name} has {array.ndim} dimensions, not {ndim}")
        meta[k, 1 : 1 + ndim] = array.shape
        if kind == "t":
            table = np.ascontiguousarray(array, dtype=np.float32)
            continue
        meta[k, 0] = offsets[kind]
        offsets[kind] += array.size
        (floats if kind == "f" else ints).append(np.ravel(array))
    fbuf = np.concatenate([np.zeros(0), *floats]).astype(np.float64)
    ibuf = np.concatenate([np.zeros(0, np.int64), *ints]).astype(np.int64)
    S, C, P = meta[5, 1], meta[7, 1], meta[11, 1]
    fwork = np.zeros(slots * 12 + 3 * (S + C + P))
    iwork = np.zeros(2 * C + P + 1, dtype=np.int64)
    return fbuf, ibuf, table, meta, fwork, iwork


@njit(cache=True, nogil=True)
def _poses(q, step_child, step_parent, step_joint, step_stack, prismatic, X):
    """Fill X (slots, 3, 4) with the world poses of the moving frames for configuration q."""
    for i in range(3):
        for j in range(4):
            X[0, i, j] = 1.0 if i == j else 0.0
    M = np.empty((4, 4))
    for k in range(len(step_child)):
        gi = step_joint[k]
        v = q[gi]
        if prismatic[gi]:
            c1 = v
            c2 = 0.0
        else:
            c1 = math.sin(v)
            c2 = 1.0 - math.cos(v)
        for i in range(4):
            for j in range(4):
                M[i, j] = (
                    step_stack[k, 0, i, j]
                    + c1 * step_stack[k, 1, i, j]
                    + c2 * step_stack[k, 2, i, j]
                )
        c, p = step_child[k], step_parent[k]
        for i in range(3):
            for j in range(4):
                s = X[p, i, 3] * M[3, j]
                for m in range(3):
                    s += X[p, i, m] * M[m, j]
                X[c, i, j] = s


@njit(cache=True, nogil=True, inline="always")
def _apply(X, slot, p, out):
    for i in range(3):
        out[i] = X[slot, i, 0] * p[0] + X[slot, i, 1] * p[1] + X[slot, i, 2] * p[2] + X[slot, i, 3]


@njit(cache=True, nogil=True)
def _obstacle_hit(
    c, r, obs_sphere_c, obs_sphere_r, box_R, box_off, box_h, cyl_R, cyl_off, cyl_rh
) -> bool:
    """Whether the sphere (c, r) touches an obstacle primitive (radius grown by EPS)."""
    r = r + EPS
    for k in range(len(obs_sphere_r)):
        d0 = c[0] - obs_sphere_c[k, 0]
        d1 = c[1] - obs_sphere_c[k, 1]
        d2 = c[2] - obs_sphere_c[k, 2]
        reach = r + obs_sphere_r[k]
        if d0 * d0 + d1 * d1 + d2 * d2 < reach * reach:
            return True
    r2 = r * r
    for k in range(len(box_h)):
        s = 0.0
        for i in range(3):
            local = c[0] * box_R[k, 0, i] + c[1] * box_R[k, 1, i] + c[2] * box_R[k, 2, i]
            e = abs(local - box_off[k, i]) - box_h[k, i]
            if e > 0.0:
                s += e * e
        if s < r2:
            return True
    for k in range(len(cyl_rh)):
        lx = c[0] * cyl_R[k, 0, 0] + c[1] * cyl_R[k, 1, 0] + c[2] * cyl_R[k, 2, 0] - cyl_off[k, 0]
        ly = c[0] * cyl_R[k, 0, 1] + c[1] * cyl_R[k, 1, 1] + c[2] * cyl_R[k, 2, 1] - cyl_off[k, 1]
        lz = c[0] * cyl_R[k, 0, 2] + c[1] * cyl_R[k, 1, 2] + c[2] * cyl_R[k, 2, 2] - cyl_off[k, 2]
        radial = max(math.hypot(lx, ly) - cyl_rh[k, 0], 0.0)
        axial = max(abs(lz) - cyl_rh[k, 1], 0.0)
        if radial * radial + axial * axial < r2:
            return True
    return False


@njit(cache=True, nogil=True, inline="always")
def _touches_obstacle(c, r, obstacles) -> bool:
    """Whether the sphere (c, r) may touch an obstacle: the table first, then the primitives.

    ``obstacles``: the fields from ``has_field`` to ``cyl_rh`` of :data:`FIELDS`.
    """
    (
        has_field,
        field,
        field_lo,
        field_spec,
        obs_sphere_c,
        obs_sphere_r,
        box_R,
        box_off,
        box_h,
        cyl_R,
        cyl_off,
        cyl_rh,
    ) = obstacles
    if has_field[0]:
        nx, ny, nz = field.shape
        h = field_spec[0]
        i = int(np.rint((c[0] - field_lo[0]) / h))
        j = int(np.rint((c[1] - field_lo[1]) / h))
        k = int(np.rint((c[2] - field_lo[2]) / h))
        inside = 0 <= i < nx and 0 <= j < ny and 0 <= k < nz
        if inside and field[i, j, k] > r + field_spec[1] + EPS:
            return False
    return _obstacle_hit(
        c, r, obs_sphere_c, obs_sphere_r, box_R, box_off, box_h, cyl_R, cyl_off, cyl_rh
    )


@njit(cache=True, nogil=True)
def _grid_clear(q, g, grid_joints, grid_origin, grid_shape, grid_spec, grid_offset, grid_table):
    """Whether distance table ``g`` proves its body pair apart at configuration q."""
    flat = grid_offset[g]
    stride = 1
    for d in range(1, -1, -1):
        j = grid_joints[g, d]
        if j < 0:
            continue
        n = grid_shape[g, d]
        idx = int(np.rint((q[j] - grid_origin[g, d]) / grid_spec[g, 0]))
        idx = min(max(idx, 0), n - 1)
        flat += idx * stride
        stride *= n
    return grid_table[flat] > grid_spec[g, 1]


@njit(cache=True, nogil=True, inline="always")
def _near(a, b, reach) -> bool:
    d0 = a[0] - b[0]
    d1 = a[1] - b[1]
    d2 = a[2] - b[2]
    return d0 * d0 + d1 * d1 + d2 * d2 < reach * reach


@njit(cache=True, nogil=True)
def _config_free(q, work, data) -> bool:
    """Whether one configuration is free of the sphere model."""
    (
        step_child,
        step_parent,
        step_joint,
        step_stack,
        prismatic,
        local,
        radii,
        cl_slot,
        cl_local,
        cl_r,
        cl_span,
        part_slot,
        part_local,
        part_r,
        part_span,
        env_parts,
    ) = data[:16]
    obstacles = data[16:28]  # has_field ... cyl_rh
    (
        grid_joints,
        grid_origin,
        grid_shape,
        grid_spec,
        grid_offset,
        grid_table,
        pair_parts,
        pair_reach2,
        pair_grid,
    ) = data[28:]
    X, C, CC, PC, cl_mark, sphere_mark, part_mark, tick = work
    tick[0] += 1
    t = tick[0]
    _poses(q, step_child, step_parent, step_joint, step_stack, prismatic, X)
    # the environment: body, cluster, sphere
    for e in range(len(env_parts)):
        p = env_parts[e]
        _apply(X, part_slot[p], part_local[p], PC[p])
        part_mark[p] = t
        if not _touches_obstacle(PC[p], part_r[p], obstacles):
            continue
        for k in range(part_span[p, 0], part_span[p, 1]):
            _apply(X, cl_slot[k], cl_local[k], CC[k])
            cl_mark[k] = t
            if not _touches_obstacle(CC[k], cl_r[k], obstacles):
                continue
            for s in range(cl_span[k, 0], cl_span[k, 1]):
                _apply(X, cl_slot[k], local[s], C[s])
            sphere_mark[k] = t
            for s in range(cl_span[k, 0], cl_span[k, 1]):
                if _touches_obstacle(C[s], radii[s], obstacles):
                    return False
    # self-collision: body pairs, their clusters, their spheres
    for k in range(len(pair_parts)):
        pa, pb = pair_parts[k, 0], pair_parts[k, 1]
        for p in (pa, pb):
            if part_mark[p] != t:
                _apply(X, part_slot[p], part_local[p], PC[p])
                part_mark[p] = t
        d0 = PC[pa, 0] - PC[pb, 0]
        d1 = PC[pa, 1] - PC[pb, 1]
        d2 = PC[pa, 2] - PC[pb, 2]
        if d0 * d0 + d1 * d1 + d2 * d2 >= pair_reach2[k]:
            continue
        g = pair_grid[k]
        if g >= 0 and _grid_clear(
            q, g, grid_joints, grid_origin, grid_shape, grid_spec, grid_offset, grid_table
        ):
            continue
        for ka in range(part_span[pa, 0], part_span[pa, 1]):
            if cl_mark[ka] != t:
                _apply(X, cl_slot[ka], cl_local[ka], CC[ka])
                cl_mark[ka] = t
            if not _near(CC[ka], PC[pb], cl_r[ka] + part_r[pb] + EPS):
                continue
            for kb in range(part_span[pb, 0], part_span[pb, 1]):
                if cl_mark[kb] != t:
                    _apply(X, cl_slot[kb], cl_local[kb], CC[kb])
                    cl_mark[kb] = t
                if not _near(CC[ka], CC[kb], cl_r[ka] + cl_r[kb] + EPS):
                    continue
                for kk in (ka, kb):
                    if sphere_mark[kk] != t:
                        for s in range(cl_span[kk, 0], cl_span[kk, 1]):
                            _apply(X, cl_slot[kk], local[s], C[s])
                        sphere_mark[kk] = t
                for sa in range(cl_span[ka, 0], cl_span[ka, 1]):
                    for sb in range(cl_span[kb, 0], cl_span[kb, 1]):
                        if _near(C[sa], C[sb], radii[sa] + radii[sb] + EPS):
                            return False
    return True


@njit(cache=True, nogil=True)
def configs_free(Q, fbuf, ibuf, table, meta, fwork, iwork):
    """Which rows of Q (N, n) the sphere model finds free; (N,) bool. Buffers: :func:`pack`."""
    data = _unpack(fbuf, ibuf, table, meta)
    work = _work_views(fwork, iwork, meta)
    out = np.empty(len(Q), dtype=np.bool_)
    for i in range(len(Q)):
        out[i] = _config_free(Q[i], work, data)
    return out


@njit(cache=True, nogil=True)
def config_free(q, fbuf, ibuf, table, meta, fwork, iwork) -> bool:
    """Whether one configuration q (n,) is free of the sphere model."""
    return _config_free(q, _work_views(fwork, iwork, meta), _unpack(fbuf, ibuf, table, meta))


@njit(cache=True, nogil=True)
def motion_status(qa, qb, step, fbuf, ibuf, table, meta, fwork, iwork):
    """Check the straight motion qa→qb sampled every ``step`` (max-norm), ends first.

    Returns:
        (status, samples checked): status 1 when every sample is free, 0 when both ends
        are free and a sample between them is not, -1 when an end is not free (the
        caller then decides with the per-sample results).
    """
    data = _unpack(fbuf, ibuf, table, meta)
    work = _work_views(fwork, iwork, meta)
    delta = 0.0
    for i in range(len(qa)):
        delta = max(delta, abs(qb[i] - qa[i]))
    count = max(1, int(math.ceil(delta / step)))
    if not _config_free(qa, work, data):
        return -1, 1
    if not _config_free(qb, work, data):
        return -1, 2
    q = np.empty(len(qa))
    checked = 2
    # midpoints of ever finer halvings (coarse to fine), each sample once
    seen = np.zeros(count + 1, dtype=np.bool_)
    seen[0] = True
    seen[count] = True
    level = 2
    while checked < count + 1:
        for k in range(1, level, 2):
            i = (k * count + level // 2) // level
            if seen[i]:
                continue
            seen[i] = True
            t = i * (1.0 / count)
            for m in range(len(qa)):
                q[m] = qa[m] + (qb[m] - qa[m]) * t
            checked += 1
            if not _config_free(q, work, data):
                return 0, checked
        level *= 2
        if level > 4 * (count + 1):
            for i in range(count + 1):
                if seen[i]:
                    continue
                seen[i] = True
                t = i * (1.0 / count)
                for m in range(len(qa)):
                    q[m] = qa[m] + (qb[m] - qa[m]) * t
                checked += 1
                if not _config_free(q, work, data):
                    return 0, checked
    return 1, checked
