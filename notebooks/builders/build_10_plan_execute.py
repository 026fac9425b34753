"""Builds notebooks/10_plan_execute.ipynb (run: python notebooks/builders/build_10_plan_execute.py)."""

from pathlib import Path

import nbformat
from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook

cells = [
    new_markdown_cell(
        "# Experiment 10: plan a path for the arm and execute it\n\n"
        "The aims of the syllabus: *plan a path for a 3DOF robotic arm and execute the same; "
        "move the 3DOF arm to a desired goal point* — and the same with the lab's 7-joint "
        "`robot_arm`. What MoveIt does with RViz's Motion Planning panel, workbench does with "
        "one call per step:\n\n"
        "| MoveIt | workbench (terminal) | here |\n|---|---|---|\n"
        "| setup assistant | `workbench setup arm3` | `run_setup('arm3')` |\n"
        "| goal: named pose / random valid / point | `--to home`, `--to random`, "
        "`--to xyz=X,Y,Z` | `planner.plan('home')` ... |\n"
        "| Plan | `workbench plan arm3 --to home` | `MotionPlanner('arm3').plan(...)` |\n"
        "| Execute | `--execute` | `execute(planner, result)` |\n\n"
        "Each plan runs OMPL (RRTConnect), shortcuts the path, times it with toppra under "
        "the joint velocity and acceleration limits, and re-checks the timed trajectory "
        "densely with exact geometry before returning it. The files it writes (a plot, "
        "snapshots) go to the output folder printed by the first cell, not next to the "
        "notebook."
    ),
    new_code_cell(
        "import os\n\n"
        "from IPython.display import Image, display\n\n"
        "from workbench.paths import notebook_output, planning_dir\n"
        "from workbench.planning.config import ConfigNotFoundError, load_config\n"
        "from workbench.planning.execute import execute\n"
        "from workbench.planning.output import animate, plot_png, show_scene, summary_table\n"
        "from workbench.planning.pipeline import MotionPlanner\n"
        "from workbench.planning.setup import run_setup\n"
        "from workbench.viz import Viewer\n\n"
        'SHORT = os.environ.get("WORKBENCH_NOTEBOOK_MODE") == "short"\n'
        'OUT = notebook_output("10_plan_execute")\n'
        'print("files go to", OUT)\n'
        "viewer = Viewer.instance()\n"
        'print("Meshcat is at", viewer.url)'
    ),
    new_markdown_cell(
        "## 1. The planning configuration\n\n"
        "`planning/ROBOT/` holds the SRDF and `planning.yaml` written by the setup assistant "
        "(notebook 09). If a robot has none yet we run the setup here, into "
        "`planning_configs/ROBOT/` in the output folder."
    ),
    new_code_cell(
        "def config_for(robot):\n"
        "    try:\n"
        "        return load_config(robot)\n"
        "    except ConfigNotFoundError:\n"
        "        pass\n"
        '    ours = OUT / "planning_configs" / robot\n'
        '    if (ours / "planning.yaml").is_file():\n'
        "        return load_config(ours)\n"
        '    print(f"no configuration for {robot}: running the setup assistant into {ours}")\n'
        "    return run_setup(robot, out_dir=ours, samples=1000 if SHORT else 10000)\n\n\n"
        'arm3 = MotionPlanner(config=config_for("arm3"), scene=planning_dir() / "scenes" / "arm3_table.yaml")\n'
        'print("group", arm3.group, "joints", arm3.joint_names, "tip", arm3.tip_link())\n'
        'print("obstacles:", arm3.scene.names())'
    ),
    new_markdown_cell(
        "## 2. Plan to a named pose, a random valid state and a point\n\n"
        "The start is `home` unless we give one. Each result carries the timed trajectory "
        "and what each stage cost."
    ),
    new_code_cell(
        'to_home = arm3.plan("home", start=[-1.2, 0.4, 0.6], seed=1)\nprint(summary_table(to_home))'
    ),
    new_code_cell(
        'to_random = arm3.plan("random", seed=2)\n'
        'print("random goal:", to_random.goal.round(3))\n'
        "print(summary_table(to_random))"
    ),
    new_code_cell(
        'to_point = arm3.plan("xyz=0.25,-0.25,0.35", seed=3)\n'
        'print("IK solution:", to_point.goal.round(3))\n'
        "print(summary_table(to_point))"
    ),
    new_markdown_cell(
        "Positions, velocities and accelerations against the limits (dashed): toppra "
        "keeps every sample inside them."
    ),
    new_code_cell(
        "display(\n"
        "    Image(\n"
        '        filename=str(plot_png(to_point.trajectory, OUT / "arm3_point.png", arm3.lower, arm3.upper))\n'
        "    )\n"
        ")"
    ),
    new_markdown_cell(
        "## 3. Execute in simulation\n\n"
        "The arm and the obstacles go into a `workbench.sim` World; the joint-level "
        "controller from `planning.yaml` tracks the trajectory and we get the tracking error."
    ),
    new_code_cell("report = execute(arm3, to_point)\nprint(report.summary())"),
    new_markdown_cell(
        "The plan as an animation in the viewer, saved as a self-contained HTML file "
        "(`arm3_plan.html` in the output folder):"
    ),
    new_code_cell(
        "viewer.clear()\n"
        "show_scene(viewer, arm3.scene)\n"
        "animate(viewer, arm3.robot, arm3.joints, to_point.trajectory)\n"
        'print("snapshot:", viewer.save_html(OUT / "arm3_plan.html"))'
    ),
    new_markdown_cell(
        "## 4. The 7-joint `robot_arm`\n\n"
        "The same steps for the lab's arm among two pillars, a block and a lamp."
    ),
    new_code_cell(
        "arm = MotionPlanner(\n"
        '    config=config_for("robot_arm"), scene=planning_dir() / "scenes" / "robot_arm_pillars.yaml"\n'
        ")\n"
        'goals = ["random"] if SHORT else ["random", "home"]\n'
        "results = {}\n"
        "for k, goal in enumerate(goals):\n"
        '    start = None if goal != "home" else results["random"].goal\n'
        "    results[goal] = arm.plan(goal, start=start, seed=10 + k)\n"
        '    print(f"--- {goal}")\n'
        "    print(summary_table(results[goal]))"
    ),
    new_code_cell(
        "if not SHORT:\n"
        '    print(execute(arm, results["random"]).summary())\n'
        "viewer.clear()\n"
        "show_scene(viewer, arm.scene)\n"
        'animate(viewer, arm.robot, arm.joints, results["random"].trajectory)\n'
        'print("snapshot:", viewer.save_html(OUT / "robot_arm_plan.html"))'
    ),
    new_markdown_cell(
        "## 5. When a request cannot be met\n\n"
        "Every failure is one specific error: a goal in collision names the two bodies, an "
        "unreachable point says so, an unknown planner suggests close names."
    ),
    new_code_cell(
        "from workbench.errors import PlanningError\n\n"
        'for goal, planner in [("q=0,1.2,2.2", None), ("xyz=2,0,0", None), ("random", "RRTConect")]:\n'
        "    try:\n"
        "        arm3.plan(goal, planner=planner)\n"
        "    except PlanningError as error:\n"
        '        print(type(error).__name__, "->", error.one_line())'
    ),
]

notebook = new_notebook(cells=cells)
notebook.metadata["kernelspec"] = {
    "name": "python3",
    "display_name": "Python 3",
    "language": "python",
}
out = Path(__file__).resolve().parents[1] / "10_plan_execute.ipynb"
nbformat.write(notebook, out)
print(f"wrote {out}")
