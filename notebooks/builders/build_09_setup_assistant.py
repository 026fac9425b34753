"""Build notebooks/09_setup_assistant.ipynb (run from the repo root)."""

import nbformat
from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook

cells = [
    new_markdown_cell(
        "# Experiment 9 — the setup assistant\n\n"
        "MoveIt's setup assistant turns a URDF into a planning configuration in twelve steps. "
        "workbench does the same from one command, `workbench setup robot_arm`, or from Python "
        "as below. Each step here calls the library; the last cell writes the same files the "
        "command writes (`robot_arm.srdf` and `planning.yaml`), but into the output folder "
        "printed by the first cell instead of where the planners look for them, so the "
        "shipped configurations stay as they are."
    ),
    new_code_cell(
        "import os\n\n"
        "from IPython.display import HTML, display\n\n"
        "from workbench.model import load_robot\n"
        "from workbench.paths import notebook_output\n"
        "from workbench.planning.collision_matrix import compute_collision_matrix\n"
        "from workbench.planning.config import load_config\n"
        "from workbench.planning.groups import infer_groups\n"
        "from workbench.planning.setup import run_setup\n\n"
        'SHORT = os.environ.get("WORKBENCH_NOTEBOOK_MODE") == "short"\n'
        "SAMPLES = 1000 if SHORT else 10000  # MoveIt's default sampling density is 10,000\n"
        "SEED = 0\n"
        'OUT = notebook_output("09_setup_assistant")\n'
        'print("files go to", OUT)'
    ),
    new_markdown_cell(
        "## Step 1 — load the robot\n"
        "The 7-joint arm of Experiment 8 (5 revolute arm joints, 2 prismatic fingers)."
    ),
    new_code_cell(
        'robot = load_robot("robot_arm")\n'
        "print(robot)\n"
        "for joint in robot.joints:\n"
        '    print(f"{joint.name:22} {joint.type:10} {joint.parent} -> {joint.child}")'
    ),
    new_markdown_cell(
        "## Step 2 — the self-collision matrix\n"
        "Every pair of links with collision geometry is classified as MoveIt does: **Adjacent** "
        "(joined by a joint), **Default** (colliding in the default pose), **Always** (colliding "
        "in more than 95 % of random poses), **Never** (not once in the random poses). The "
        "remaining pairs must be checked while planning. The manual expects only Adjacent and "
        "Never entries for this arm."
    ),
    new_code_cell(
        "matrix = compute_collision_matrix(robot, samples=SAMPLES, seed=SEED)\n"
        'print(f"{matrix.sampled} random states in {matrix.seconds:.2f} s")\n'
        "print(matrix.summary())\n"
        "display(HTML(matrix.to_html()))"
    ),
    new_markdown_cell(
        "The same result as the square view of the assistant (A adjacent, N never, "
        "blank = checked while planning):"
    ),
    new_code_cell("display(HTML(matrix.to_html(grid=True)))"),
    new_markdown_cell(
        "## Steps 3–7 — virtual joint, planning groups, poses, end effector, passive joints\n"
        "The arm is the chain from the root link to the link that carries the fingers; the "
        "fingers form the hand. Grouping the arm as a chain (not a list of joints that includes "
        "the fixed `bottom_joint`) avoids the manual's *Group 'robot_arm' is not a chain* error."
    ),
    new_code_cell(
        "guess = infer_groups(robot)\n"
        'print("arm chain :", guess.base_link, "->", guess.tip_link)\n'
        'print("arm joints:", guess.arm_joints)\n'
        'print("hand links:", guess.hand_links)'
    ),
    new_markdown_cell(
        "## Steps 1–12 in one call\n"
        "The group is named `robot_arm` and the `home` pose is the one saved in the manual. "
        "Steps 8 (3D perception) and 9 (Gazebo) need nothing: workbench simulates the URDF "
        "directly. Step 10 is the joint controller that executes plans in `workbench.sim`. "
        "The files land in `robot_arm_config/` in the output folder."
    ),
    new_code_cell(
        "manual_home = [-0.1772, -0.1036, -1.0416, -0.5817, 0.6856]\n"
        "config = run_setup(\n"
        '    "robot_arm",\n'
        '    out_dir=OUT / "robot_arm_config",\n'
        "    samples=SAMPLES,\n"
        "    seed=SEED,\n"
        '    group="robot_arm",\n'
        '    poses={"home": manual_home},\n'
        "    log=print,\n"
        ")"
    ),
    new_code_cell(
        'print((OUT / "robot_arm_config" / "robot_arm.srdf").read_text()[:1500])\n'
        'print((OUT / "robot_arm_config" / "planning.yaml").read_text())'
    ),
    new_markdown_cell(
        "## Using the configuration\n"
        "The planner reads it back with `load_config`. Acceleration limits are not in URDFs: "
        "the setup writes twice the velocity limit (full speed in 0.5 s)."
    ),
    new_code_cell(
        'loaded = load_config(OUT / "robot_arm_config")\n'
        "joints = loaded.srdf.group_joints(loaded.group, robot)\n"
        'print("group", loaded.group, joints)\n'
        'print("velocity limits     ", loaded.velocity_limits(joints))\n'
        'print("acceleration limits ", loaded.acceleration_limits(joints))\n'
        'print("home", loaded.srdf.group_state(loaded.group, "home").values)'
    ),
    new_markdown_cell(
        "## Step 10 at work — the controller moves the arm to `home` in simulation\n"
        "A rest-to-rest cubic from zero to the `home` pose, tracked by the inverse-dynamics "
        "controller (`workbench plan --execute` does this with a planned trajectory)."
    ),
    new_code_cell(
        "import numpy as np\n\n"
        "from workbench.sim import JointTrajectory, World\n\n"
        "world = World()\n"
        'world.add_robot("robot_arm", X_WB=[0, 0, 0.05])\n'
        "world.build()\n"
        "goal = np.array(manual_home)\n"
        "t = np.linspace(0.0, 2.0, 50)\n"
        "s = t / t[-1]\n"
        "q = (3 * s**2 - 2 * s**3)[:, None] * goal\n"
        "qd = ((6 * s - 6 * s**2) / t[-1])[:, None] * goal\n"
        'report = world.track_trajectory("robot_arm", JointTrajectory(joints, t, q, qd))\n'
        "print(report.summary())"
    ),
    new_markdown_cell(
        "## The 3-DOF arm\nThe same for `arm3` (no gripper, so no hand group), into "
        "`arm3_config/` in the output folder:"
    ),
    new_code_cell(
        'arm3 = run_setup("arm3", out_dir=OUT / "arm3_config", samples=SAMPLES, seed=SEED, log=print)\n'
        "display(HTML(arm3.collision_matrix.to_html(grid=True)))"
    ),
]

nb = new_notebook(cells=cells)
nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
nbformat.write(nb, "notebooks/09_setup_assistant.ipynb")
