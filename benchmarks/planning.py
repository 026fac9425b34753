"""Planning benchmark: workbench's pipeline against a MoveIt-like OMPL baseline, same run, same problems.

Suites:

* ``panda`` -- MotionBenchMaker for the Franka Panda (bookshelf_small/tall/thin,
  box, cage, table_pick, table_under_pick; 100 problems each). The problems,
  the Panda URDF with collision meshes and its SRDF ship in the
  ``vamp-planner`` 0.6.4 source distribution (``resources/panda/``); the
  script fetches it once with ``pip download`` into a cache directory, or
  uses ``--resources DIR`` (a directory holding ``panda.urdf``, ``panda.srdf``
  and ``problems.tar.bz2``).
* ``lab`` -- the lab arms (robot_arm, arm3) in their scenes from
  ``planning/scenes/``, between seeded random valid states.

Per problem both planners get the same start, goal, time limit (1 s) and
seed. workbench plans with its sphere model (exact geometry confirms what the
spheres reject) and steps edges at ``--step`` rad; the baseline is OMPL
RRTConnect with one exact Drake collision query per state and OMPL's discrete
motion validator at 0.005 of the space's extent (MoveIt's default), with the
same simplifier. Both paths are then timed by toppra and re-checked densely
with exact geometry. Reported per scene: success, median and p95 of plan,
simplify, plan+simplify and timing (ms), path length, and re-check failures.

Run ``python benchmarks/planning.py`` (all problems) or ``--quick`` (3 per scene).
"""

from __future__ import annotations

import argparse
import json
import logging
import os
import re
import subprocess
import sys
import tarfile
import time
from pathlib import Path

import numpy as np

VAMP = "vamp-planner==0.6.4"
PANDA_SCENES = (
    "bookshelf_small",
    "bookshelf_tall",
    "bookshelf_thin",
    "box",
    "cage",
    "table_pick",
    "table_under_pick",
)
HERE = Path(__file__).resolve().parent
RESULTS = HERE / "results" / "planning.json"


# --- data -----------------------------------------------------------------------------------


def fetch_panda(cache: Path) -> Path:
    """The vamp-planner sdist's ``resources/panda`` directory, downloaded once into ``cache``."""
    target = cache / "panda"
    if (target / "problems.tar.bz2").is_file():
        return target
    cache.mkdir(parents=True, exist_ok=True)
    print(f"fetching {VAMP} (source distribution, about 65 MB) into {cache} ...", flush=True)
    subprocess.run(
        [
            sys.executable,
            "-m",
            "pip",
            "download",
            "--no-deps",
            "--no-binary",
            "vamp-planner",
            VAMP,
            "-d",
            str(cache),
        ],
        check=True,
        stdout=subprocess.DEVNULL,
    )
    archive = next(cache.glob("vamp_planner-*.tar.gz"))
    with tarfile.open(archive) as tar:
        members = [m for m in tar.getmembers() if "/resources/panda/" in m.name]
        for member in members:
            member.name = member.name.split("/resources/", 1)[1]
        tar.extractall(cache, members=members, filter="data")
    archive.unlink()
    return target


def panda_urdf(resources: Path, cache: Path) -> Path:
    """The Panda URDF with its ``package://meshes/`` URIs made absolute."""
    text = (resources / "panda.urdf").read_text()
    out = cache / "panda_abs.urdf"
    out.write_text(text.replace("package://meshes/", f"{(resources / 'meshes').resolve()}/"))
    return out


def _quat_to_rpy(xyzw) -> np.ndarray:
    from scipy.spatial.transform import Rotation

    return Rotation.from_quat(np.asarray(xyzw, float)).as_euler("xyz")


def _scene_from_moveit(data) -> object:
    from workbench.planning.scene import PlanningScene

    scene = PlanningScene()
    for obj in data["world"]["collision_objects"]:
        prim, pose = obj["primitives"][0], obj["primitive_poses"][0]
        xyz, rpy = np.asarray(pose["position"], float), _quat_to_rpy(pose["orientation"])
        dims = prim["dimensions"]
        if prim["type"] == "box":
            scene.add_box(obj["id"], dims, xyz, rpy)
        elif prim["type"] == "cylinder":
            scene.add_cylinder(obj["id"], dims[1], dims[0], xyz, rpy)
        elif prim["type"] == "sphere":
            scene.add_sphere(obj["id"], dims[0], xyz)
    return scene


def load_panda_problems(resources: Path, per_scene: int) -> dict[str, list[dict]]:
    """MotionBenchMaker problems: {scene: [{index, scene, start, goal}, ...]}."""
    import yaml

    joints = [f"panda_joint{i}" for i in range(1, 8)]
    files: dict[tuple[str, int], dict[str, object]] = {}
    with tarfile.open(resources / "problems.tar.bz2", "r:bz2") as tar:
        for member in tar.getmembers():
            if not member.isfile():
                continue
            _, folder, filename = member.name.split("/")
            scene = folder.replace("_panda", "")
            index = int(re.findall(r"\d+", filename)[0])
            if index > per_scene:
                continue
            data = yaml.load(tar.extractfile(member).read(), Loader=yaml.CSafeLoader)
            kind = "scene" if "scene" in filename else "request"
            files.setdefault((scene, index), {})[kind] = data
    problems: dict[str, list[dict]] = {name: [] for name in PANDA_SCENES}
    for (scene, index), parts in sorted(files.items()):
        request = parts["request"]
        state = request["start_state"]["joint_state"]
        start = [state["position"][state["name"].index(j)] for j in joints]
        goal_constraints = request["goal_constraints"][0]["joint_constraints"]
        goal_map = {c["joint_name"]: c["position"] for c in goal_constraints}
        problems[scene].append(
            {
                "index": index,
                "scene": _scene_from_moveit(parts["scene"]),
                "start": np.array(start),
                "goal": np.array([goal_map[j] for j in joints]),
            }
        )
    return problems


def lab_problems(per_scene: int, seed: int) -> dict[str, tuple[object, list[dict]]]:
    """Random valid start/goal pairs for the lab arms in their shipped scenes."""
    from workbench.paths import planning_dir
    from workbench.planning.pipeline import MotionPlanner
    from workbench.planning.scene import load_scene
    from workbench.planning.setup import run_setup

    suites = {}
    for robot, scene_file in (("robot_arm", "robot_arm_pillars.yaml"), ("arm3", "arm3_table.yaml")):
        config = run_setup(robot, write=False, seed=seed)
        scene = load_scene(planning_dir() / "scenes" / scene_file)
        planner = MotionPlanner(config=config, scene=scene)
        rng = np.random.default_rng(seed)
        problems = []
        while len(problems) < per_scene:
            pair = [rng.uniform(planner.lower, planner.upper) for _ in range(2)]
            if all(planner.is_free(q) for q in pair):
                problems.append(
                    {"index": len(problems), "scene": scene, "start": pair[0], "goal": pair[1]}
                )
        suites[f"{robot}/{Path(scene_file).stem}"] = (config, problems)
    return suites


# --- running -------------------------------------------------------------------------------


def run_problem(config, problem, *, time_limit: float, seed: int, step: float) -> dict[str, dict]:
    """Both planners on one problem; returns {"workbench": {...}, "baseline": {...}}."""
    from workbench.errors import PlanningError
    from workbench.planning.ompl_planner import plan as ompl_plan
    from workbench.planning.pipeline import MotionPlanner

    planner = MotionPlanner(config=config, scene=problem["scene"], edge_step=step)
    out: dict[str, dict] = {}
    try:
        result = planner.plan(
            problem["goal"], start=problem["start"], time_limit=time_limit, seed=seed
        )
        out["workbench"] = {
            "ok": True,
            "plan": result.times["solve"],
            "simplify": result.times["simplify"],
            "timing": result.times["timing"],
            "recheck": result.times["recheck"],
            "length": result.path_length,
            "recheck_ok": result.recheck_ok,
        }
    except PlanningError as error:
        out["workbench"] = {"ok": False, "error": type(error).__name__}

    def exact(q: np.ndarray) -> bool:
        return planner.world.is_free(planner.joints.full(q))

    try:
        base = ompl_plan(
            planner.lower,
            planner.upper,
            problem["start"],
            problem["goal"],
            exact,
            resolution=0.005,
            planner="RRTConnect",
            time_limit=time_limit,
            seed=seed,
        )
        began = time.perf_counter()
        trajectory = planner.time(base.path)
        timing = time.perf_counter() - began
        began = time.perf_counter()
        _, ok = planner.recheck(trajectory)
        out["baseline"] = {
            "ok": True,
            "plan": base.solve_time,
            "simplify": base.simplify_time,
            "timing": timing,
            "recheck": time.perf_counter() - began,
            "length": float(np.linalg.norm(np.diff(base.path, axis=0), axis=1).sum()),
            "recheck_ok": ok,
        }
    except PlanningError as error:
        out["baseline"] = {"ok": False, "error": type(error).__name__}
    return out


def warm_up(suites: dict[str, tuple[object, list[dict]]], step: float) -> float:
    """Compile (or load from numba's cache) the sphere kernel once; returns the seconds taken.

    The first sphere checker of a process does it while it is built, outside any plan's timing.
    """
    from workbench.planning.pipeline import MotionPlanner
    from workbench.planning.spheres import kernel_load_seconds

    config, problems = next(iter(suites.values()))
    MotionPlanner(config=config, scene=problems[0]["scene"], edge_step=step)
    return kernel_load_seconds()


def summarize(rows: list[dict]) -> dict:
    ok = [r for r in rows if r["ok"]]

    def stat(key, q):
        values = [r[key] for r in ok]
        return float(np.percentile(values, q)) if values else float("nan")

    both = [r["plan"] + r["simplify"] for r in ok]
    return {
        "problems": len(rows),
        "success": len(ok) / max(len(rows), 1),
        "plan_median_ms": stat("plan", 50) * 1e3,
        "plan_p95_ms": stat("plan", 95) * 1e3,
        "simplify_median_ms": stat("simplify", 50) * 1e3,
        "simplify_p95_ms": stat("simplify", 95) * 1e3,
        "plan_simplify_median_ms": float(np.median(both)) * 1e3 if both else float("nan"),
        "plan_simplify_p95_ms": float(np.percentile(both, 95)) * 1e3 if both else float("nan"),
        "timing_median_ms": stat("timing", 50) * 1e3,
        "timing_p95_ms": stat("timing", 95) * 1e3,
        "length_median": stat("length", 50),
        "recheck_failures": sum(1 for r in ok if not r["recheck_ok"]),
    }


def machine() -> dict:
    from machine import describe

    return describe(("drake", "ompl", "toppra", "numpy", "numba"))


def print_table(summary: dict[str, dict[str, dict]]) -> None:
    header = (
        f"{'scene':<28}{'planner':<10}{'ok %':>6}{'plan med':>10}{'p95':>9}{'simp med':>10}"
        f"{'p95':>9}{'p+s med':>10}{'p95':>9}{'toppra':>8}{'p95':>8}{'length':>8}{'rechk':>7}{'x faster':>9}"
    )
    print(header)
    print("-" * len(header))
    for scene, pair in summary.items():
        ratio = (
            pair["baseline"]["plan_simplify_median_ms"]
            / pair["workbench"]["plan_simplify_median_ms"]
        )
        for who in ("workbench", "baseline"):
            s = pair[who]
            print(
                f"{scene:<28}{who:<10}{s['success'] * 100:>6.1f}{s['plan_median_ms']:>10.2f}"
                f"{s['plan_p95_ms']:>9.1f}{s['simplify_median_ms']:>10.2f}{s['simplify_p95_ms']:>9.1f}"
                f"{s['plan_simplify_median_ms']:>10.2f}{s['plan_simplify_p95_ms']:>9.1f}"
                f"{s['timing_median_ms']:>8.2f}{s['timing_p95_ms']:>8.1f}{s['length_median']:>8.2f}"
                f"{s['recheck_failures']:>7d}" + (f"{ratio:>9.1f}" if who == "workbench" else "")
            )


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="3 problems per scene")
    parser.add_argument("--problems", type=int, default=100, help="problems per scene (max 100)")
    parser.add_argument("--suite", choices=("panda", "lab", "all"), default="all")
    parser.add_argument("--resources", type=Path, help="a local resources/panda directory")
    parser.add_argument(
        "--cache",
        type=Path,
        default=Path(os.environ.get("XDG_CACHE_HOME", Path.home() / ".cache"))
        / "workbench"
        / "vamp-planner-0.6.4",
    )
    parser.add_argument("--time-limit", type=float, default=1.0)
    parser.add_argument("--step", type=float, default=0.05, help="workbench edge step, rad")
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--scenes", help="comma-separated subset of the Panda scenes")
    parser.add_argument("--out", type=Path, default=RESULTS)
    args = parser.parse_args(argv)
    logging.getLogger("workbench.model").setLevel(logging.ERROR)
    per_scene = 3 if args.quick else args.problems
    info = machine()
    print(
        f"machine: {info['cpu']}, {info['cores']} cores; python {info['python']}, drake "
        f"{info['drake']}, ompl {info['ompl']}, toppra {info['toppra']}, numba {info['numba']}; "
        f"load average {info['load_average'][0]:.1f}; seed {args.seed}; "
        f"time limit {args.time_limit} s; one thread"
    )
    suites: dict[str, tuple[object, list[dict]]] = {}
    if args.suite in ("panda", "all"):
        from workbench.planning.setup import run_setup

        resources = args.resources or fetch_panda(args.cache)
        args.cache.mkdir(parents=True, exist_ok=True)
        config = run_setup(
            str(panda_urdf(resources, args.cache)),
            srdf=resources / "panda.srdf",
            samples=0,
            write=False,
        )
        wanted = args.scenes.split(",") if args.scenes else PANDA_SCENES
        for scene, problems in load_panda_problems(resources, per_scene).items():
            if scene in wanted:
                suites[f"panda/{scene}"] = (config, problems)
    if args.suite in ("lab", "all"):
        suites.update(lab_problems(per_scene, args.seed))

    compile_seconds = warm_up(suites, args.step)
    print(
        f"sphere kernel compile/load (once per process, not in any time below): "
        f"{compile_seconds:.2f} s"
    )
    info["kernel_compile_s"] = compile_seconds
    rows: dict[str, dict[str, list]] = {}
    began = time.perf_counter()
    for name, (config, problems) in suites.items():
        rows[name] = {"workbench": [], "baseline": []}
        for k, problem in enumerate(problems):
            result = run_problem(
                config, problem, time_limit=args.time_limit, seed=args.seed + k, step=args.step
            )
            for who in ("workbench", "baseline"):
                rows[name][who].append(result[who])
        print(
            f"  {name}: {len(problems)} problems ({time.perf_counter() - began:.0f} s so far)",
            flush=True,
        )
    summary = {name: {who: summarize(r[who]) for who in r} for name, r in rows.items()}
    all_rows = {
        who: [x for r in rows.values() for x in r[who]] for who in ("workbench", "baseline")
    }
    panda_rows = {
        who: [x for name, r in rows.items() if name.startswith("panda/") for x in r[who]]
        for who in ("workbench", "baseline")
    }
    if panda_rows["workbench"]:
        summary["panda (all)"] = {who: summarize(panda_rows[who]) for who in panda_rows}
    summary["all"] = {who: summarize(all_rows[who]) for who in all_rows}
    print()
    print_table(summary)
    args.out.parent.mkdir(parents=True, exist_ok=True)
    args.out.write_text(
        json.dumps(
            {
                "machine": info,
                "args": {k: str(v) for k, v in vars(args).items()},
                "summary": summary,
                "rows": rows,
            },
            indent=1,
            default=str,
        )
    )
    print(f"\nwrote {args.out}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
