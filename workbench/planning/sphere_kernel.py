"""Compiled (numba) sphere-model collision checks of one configuration or one straight motion.

The same checks as :meth:`workbench.planning.spheres.SphereChecker.configs_free_reference`
(the numpy version), in one compiled loop that stops at the first collision:

1. forward kinematics of the group's moving frames (3x4 poses, one Rodrigues
   step per joint);
2. the exact distance tables of body pairs the spheres cannot resolve;
3. every moving sphere against the obstacles' distance table, and against the
   obstacle primitives (spheres, boxes, cylinders) when the table cannot clear it;
4. self-collision: bounding spheres of body pairs, then their sphere pairs.

Every comparison is made with the radii grown by :data:`EPS`, so the kernel
never accepts a configuration the numpy version rejects because of a
different rounding order; it may reject a few more (within a nanometre of
contact). All arrays are packed once per checker by
:meth:`~workbench.planning.spheres.SphereChecker.kernel_data`, in the order of
:data:`FIELDS`.
"""

from __future__ import annotations

import math

import numpy as np

from workbench.optional import require

njit = require("numba").njit

#: Growth of every radius in the compiled comparisons, m.
EPS = 1e-9

#: The packed arrays, in the order the kernels take them.
FIELDS = (
    "step_child",  # (J,) int64: slot a group joint moves
    "step_parent",  # (J,) int64: its parent's slot (0 = world)
    "step_joint",  # (J,) int64: the joint's index in the group vector
    "step_stack",  # (J, 3, 4, 4) float64: X_PC(q) = M0 + c1 M1 + c2 M2
    "prismatic",  # (n,) bool
    "local",  # (S, 3) sphere centres in their slot's frame, m
    "owner_slot",  # (S,) int64
    "radii",  # (S,) float64, m (padding included)
    "env_spheres",  # (E,) int64: spheres checked against the obstacles
    "has_field",  # (1,) bool: the obstacles' distance table exists
    "field",  # (X, Y, Z) float32 distance table, m
    "field_lo",  # (3,) its lower corner, m
    "field_spec",  # (2,) spacing and slack (half the cell diagonal), m
    "obs_sphere_c",  # (Ks, 3) obstacle spheres
    "obs_sphere_r",  # (Ks,)
    "box_R",  # (Kb, 3, 3) box rotations (world from box)
    "box_off",  # (Kb, 3) p @ R
    "box_h",  # (Kb, 3) half sizes
    "cyl_R",  # (Kc, 3, 3)
    "cyl_off",  # (Kc, 3)
    "cyl_rh",  # (Kc, 2) radius and half length
    "grid_joints",  # (G, 2) int64 group indices of a table's axes (-1 = unused)
    "grid_origin",  # (G, 2) first value of each axis
    "grid_shape",  # (G, 2) int64 axis lengths (1 when unused)
    "grid_spec",  # (G, 2) step and margin
    "grid_offset",  # (G,) int64 start of each table in grid_table
    "grid_table",  # (sum,) float64 tables, row-major, concatenated
    "bound_slot",  # (B,) int64 slot of each body's bounding sphere
    "bound_local",  # (B, 3) bounding sphere centres in the slot frame
    "pair_body",  # (P, 2) int64 body pairs checked with spheres (indices into bounds)
    "pair_reach2",  # (P,) (bounding radii sum + EPS)^2
    "pair_start",  # (P,) int64 first sphere pair of each body pair
    "pair_count",  # (P,) int64
    "sp_ab",  # (SP, 2) int64 sphere pairs
    "sp_r2",  # (SP,) (radius sum + EPS)^2
)


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


@njit(cache=True, nogil=True)
def _config_free(
    q,
    X,
    C,
    step_child,
    step_parent,
    step_joint,
    step_stack,
    prismatic,
    local,
    owner_slot,
    radii,
    env_spheres,
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
    grid_joints,
    grid_origin,
    grid_shape,
    grid_spec,
    grid_offset,
    grid_table,
    bound_slot,
    bound_local,
    pair_body,
    pair_reach2,
    pair_start,
    pair_count,
    sp_ab,
    sp_r2,
) -> bool:
    """Whether one configuration is free of the sphere model (X, C: work arrays)."""
    _poses(q, step_child, step_parent, step_joint, step_stack, prismatic, X)
    # distance tables of pairs the spheres cannot resolve
    for g in range(len(grid_offset)):
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
        if grid_table[flat] <= grid_spec[g, 1]:
            return False
    # the environment
    c = np.empty(3)
    if len(env_spheres):
        nx, ny, nz = field.shape
        h, slack = field_spec[0], field_spec[1]
        for e in range(len(env_spheres)):
            s = env_spheres[e]
            _apply(X, owner_slot[s], local[s], c)
            C[s, 0], C[s, 1], C[s, 2] = c[0], c[1], c[2]
            r = radii[s]
            if has_field[0]:
                i = int(np.rint((c[0] - field_lo[0]) / h))
                j = int(np.rint((c[1] - field_lo[1]) / h))
                k = int(np.rint((c[2] - field_lo[2]) / h))
                inside = 0 <= i < nx and 0 <= j < ny and 0 <= k < nz
                if inside and field[i, j, k] > r + slack + EPS:
                    continue
            if _obstacle_hit(
                c, r, obs_sphere_c, obs_sphere_r, box_R, box_off, box_h, cyl_R, cyl_off, cyl_rh
            ):
                return False
    # self-collision: bounding spheres, then sphere pairs
    if len(pair_count):
        B = len(bound_slot)
        bounds = np.empty((B, 3))
        for b in range(B):
            _apply(X, bound_slot[b], bound_local[b], bounds[b])
        done = np.zeros(len(radii), dtype=np.bool_)
        for s in env_spheres:
            done[s] = True
        for p in range(len(pair_count)):
            a, b = pair_body[p, 0], pair_body[p, 1]
            d0 = bounds[a, 0] - bounds[b, 0]
            d1 = bounds[a, 1] - bounds[b, 1]
            d2 = bounds[a, 2] - bounds[b, 2]
            if d0 * d0 + d1 * d1 + d2 * d2 >= pair_reach2[p]:
                continue
            for t in range(pair_start[p], pair_start[p] + pair_count[p]):
                sa, sb = sp_ab[t, 0], sp_ab[t, 1]
                if not done[sa]:
                    _apply(X, owner_slot[sa], local[sa], C[sa])
                    done[sa] = True
                if not done[sb]:
                    _apply(X, owner_slot[sb], local[sb], C[sb])
                    done[sb] = True
                d0 = C[sa, 0] - C[sb, 0]
                d1 = C[sa, 1] - C[sb, 1]
                d2 = C[sa, 2] - C[sb, 2]
                if d0 * d0 + d1 * d1 + d2 * d2 < sp_r2[t]:
                    return False
    return True


@njit(cache=True, nogil=True)
def configs_free(Q, slots, data):
    """Which rows of Q (N, n) the sphere model finds free; (N,) bool. ``data``: :data:`FIELDS`."""
    X = np.empty((slots, 3, 4))
    C = np.empty((len(data[5]), 3))
    out = np.empty(len(Q), dtype=np.bool_)
    for i in range(len(Q)):
        out[i] = _config_free(Q[i], X, C, *data)
    return out


@njit(cache=True, nogil=True)
def config_free(q, slots, data) -> bool:
    """Whether one configuration q (n,) is free of the sphere model."""
    X = np.empty((slots, 3, 4))
    C = np.empty((len(data[5]), 3))
    return _config_free(q, X, C, *data)


@njit(cache=True, nogil=True)
def motion_status(qa, qb, step, slots, data):
    """Check the straight motion qa→qb sampled every ``step`` (max-norm), ends first.

    Returns:
        (status, samples checked): status 1 when every sample is free, 0 when both ends
        are free and a sample between them is not, -1 when an end is not free (the
        caller then decides with the per-sample results).
    """
    X = np.empty((slots, 3, 4))
    C = np.empty((len(data[5]), 3))
    delta = 0.0
    for i in range(len(qa)):
        delta = max(delta, abs(qb[i] - qa[i]))
    count = max(1, int(math.ceil(delta / step)))
    if not _config_free(qa, X, C, *data):
        return -1, 1
    if not _config_free(qb, X, C, *data):
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
            if not _config_free(q, X, C, *data):
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
                if not _config_free(q, X, C, *data):
                    return 0, checked
    return 1, checked
