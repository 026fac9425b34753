"""Summaries and printed tables of ``benchmarks/slam.py``: one row per run, one per method.

A row is a dict with ``method``, ``ate`` (m, None for a failed run),
``rel_<d>m`` (the relative error's dict, None for a failed run), optional
``level``/``seed``/``rbpf_seed``, ``cpu_s`` and ``peak_mb`` (None where not
measured) and, for failed runs, ``status``.
"""

from __future__ import annotations

import numpy as np


def _num(value: float | None, spec: str, width: int) -> str:
    """``value`` formatted with ``spec``, or ``-`` when None or NaN, right-aligned."""
    if value is None or not np.isfinite(value):
        return "-".rjust(width)
    return format(value, spec).rjust(width)


def _mean(values: list) -> float | None:
    kept = [v for v in values if v is not None]
    return float(np.mean(kept)) if kept else None


def label(row: dict) -> str:
    """The method, with rbpf-slam's seed when there is one."""
    seed = row.get("rbpf_seed")
    return row["method"] if seed is None else f"{row['method']} ({seed})"


def summary_entry(runs: list[dict], base: dict | None) -> dict:
    """Median, spread and means over ``runs`` of one method; ratios to ``base`` (workbench's)."""
    ok = [r for r in runs if r["ate"] is not None]
    entry: dict = {"method": runs[0]["method"], "runs": len(runs), "failed": len(runs) - len(ok)}
    if not ok:
        return entry
    ates = [r["ate"] for r in ok]
    entry.update(
        ate=float(np.mean(ates)),
        ate_median=float(np.median(ates)),
        ate_min=float(np.min(ates)),
        ate_max=float(np.max(ates)),
        rel_1m_trans=_mean([r["rel_1m"]["trans_mean"] for r in ok]),
        rel_1m_rot=_mean([r["rel_1m"]["rot_mean"] for r in ok]),
        cpu_s=_mean([r.get("cpu_s") for r in ok]),
        peak_mb=max((r["peak_mb"] for r in ok if r.get("peak_mb")), default=None),
    )
    if "rel_5m" in ok[0]:
        entry["rel_5m_trans"] = _mean([r["rel_5m"]["trans_mean"] for r in ok])
    for key in ("realtime_factor", "cpu_realtime_factor"):
        if all(r.get(key) for r in ok):
            entry[key] = float(np.mean([r[key] for r in ok]))
    if base is not None and base.get("ate"):
        entry["ate_ratio_to_workbench"] = entry["ate"] / base["ate"]
        entry["ate_median_ratio_to_workbench"] = entry["ate_median"] / base["ate_median"]
        entry["rel_1m_ratio_to_workbench"] = entry["rel_1m_trans"] / base["rel_1m_trans"]
        if entry["cpu_s"] and base.get("cpu_s"):
            entry["cpu_ratio_to_workbench"] = entry["cpu_s"] / base["cpu_s"]
    return entry


def summarise(rows: list[dict], group: str | None = None) -> list[dict]:
    """One entry per method (per value of ``group``, e.g. ``level``), methods in row order."""
    out = []
    for value in dict.fromkeys(r.get(group) for r in rows) if group else [None]:
        selected = [r for r in rows if group is None or r[group] == value]
        base = None
        for method in dict.fromkeys(r["method"] for r in selected):
            entry = summary_entry([r for r in selected if r["method"] == method], base)
            if group is not None:
                entry = {group: value, **entry}
            if method == "workbench":
                base = entry
            out.append(entry)
    return out


def print_runs(rows: list[dict]) -> None:
    """One line per run: ATE, relative errors at 1 m and 5 m, CPU, memory, wall time."""
    head = (
        f"{'level':7} {'seed':>4} {'method':22} {'ATE m':>7} {'rel 1m: trans m':>17} "
        f"{'rot deg':>13} {'rel 5m: trans m':>17} {'CPU s':>7} {'peak MB':>8} {'wall s':>7} "
        f"{'x real time':>11}"
    )
    print(head)
    print("-" * len(head))
    for r in rows:
        start = f"{r['level']:7} {r['seed']:4d} {label(r):22}"
        if r["ate"] is None:
            print(f"{start} {r['status']}")
            continue
        a, b = r["rel_1m"], r["rel_5m"]
        print(
            f"{start} {r['ate']:7.3f} "
            f"{a['trans_mean']:8.3f} ± {a['trans_std']:5.3f} "
            f"{a['rot_mean']:5.2f} ± {a['rot_std']:5.2f} "
            f"{b['trans_mean']:8.3f} ± {b['trans_std']:5.3f} {_num(r.get('cpu_s'), '.1f', 7)} "
            f"{_num(r.get('peak_mb'), '.0f', 8)} {_num(r.get('wall_s'), '.1f', 7)} "
            f"{_num(r.get('realtime_factor'), '.0f', 11)}"
        )


def print_summary(summary: list[dict], group: str | None = None) -> None:
    """One line per method: ATE median [min-max], mean relative errors, CPU, memory, ratios."""
    first = f"{group:7} " if group else ""
    head = (
        f"{first}{'method':16} {'runs':>4} {'ATE m median [min-max]':>24} {'rel 1m m':>8} "
        f"{'rel 1m deg':>10} {'CPU s':>7} {'peak MB':>8} {'ATE x wb':>8} {'CPU x wb':>8}"
    )
    print(head)
    for s in summary:
        start = (f"{s[group]:7} " if group else "") + f"{s['method']:16} {s['runs']:4d}"
        if "ate" not in s:
            print(f"{start} all {s['failed']} runs failed")
            continue
        spread = f"{s['ate_median']:.3f} [{s['ate_min']:.3f}-{s['ate_max']:.3f}]"
        failed = f"  ({s['failed']} failed)" if s["failed"] else ""
        print(
            f"{start} {spread:>24} {_num(s['rel_1m_trans'], '.3f', 8)} "
            f"{_num(s['rel_1m_rot'], '.2f', 10)} {_num(s['cpu_s'], '.1f', 7)} "
            f"{_num(s['peak_mb'], '.0f', 8)} "
            f"{_num(s.get('ate_median_ratio_to_workbench'), '.1f', 8)} "
            f"{_num(s.get('cpu_ratio_to_workbench'), '.2f', 8)}{failed}"
        )
