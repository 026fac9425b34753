"""Builds notebooks/05_urdf.ipynb (run: python notebooks/builders/build_05_urdf.py)."""

from pathlib import Path

import nbformat
from nbformat.v4 import new_code_cell, new_markdown_cell, new_notebook

cells = [
    new_markdown_cell(
        "# Experiment 5: a robot model with URDF\n\n"
        "We build R2D2 the way the lab does: one link, then legs joined by fixed joints, "
        "origins, colours, the finished model, movable joints, and finally collision and "
        "physical properties. After each step we run the three tools of the lab:\n\n"
        "| ROS | workbench (terminal) | here |\n|---|---|---|\n"
        "| `check_urdf FILE` | `workbench check FILE` | `check_robot(FILE)` |\n"
        "| `urdf_to_graphviz FILE` | `workbench graph FILE` | `graph_robot(FILE)` |\n"
        "| `roslaunch urdf_tutorial display.launch model:=FILE` | `workbench show FILE` "
        "| `viewer.show_robot(load_robot(FILE))` |\n\n"
        "The models are in the project's `urdf/` folder; a name such as `myfirst` means "
        "`urdf/myfirst.urdf`. What the notebook writes (snapshots, a URDF of your own, a "
        "picture) goes to the output folder printed by the first cell, not next to the "
        "notebook."
    ),
    new_code_cell(
        "import os\n\n"
        "from IPython.display import Image, display\n\n"
        "from workbench.model import check_robot, graph_robot, load_robot, resolve_robot_path\n"
        "from workbench.paths import notebook_output\n"
        "from workbench.viz import Viewer\n\n"
        'SHORT = os.environ.get("WORKBENCH_NOTEBOOK_MODE") == "short"\n'
        'OUT = notebook_output("05_urdf")\n'
        'print("files go to", OUT)\n'
        "viewer = Viewer.instance()\n"
        'print("Meshcat is at", viewer.url, "- open it in a browser to see each step")'
    ),
    new_markdown_cell(
        "Each step prints the URDF, checks it, draws its graph, shows it in the viewer and "
        "writes a self-contained HTML snapshot, `NAME.html` in the output folder, that you "
        "can open without a server."
    ),
    new_code_cell(
        "def step(name, q=None, show_file=True):\n"
        "    path = resolve_robot_path(name)\n"
        "    if show_file:\n"
        "        print(path.read_text())\n"
        "    report = check_robot(path)\n"
        "    print(report)\n"
        "    display(graph_robot(path))\n"
        "    robot = load_robot(path)\n"
        "    viewer.clear()\n"
        "    q = robot.default_positions() if q is None else robot.positions_from(q)\n"
        "    viewer.show_robot(robot, q)\n"
        "    viewer.frame_robot(robot, q)\n"
        '    print("snapshot:", viewer.save_html(OUT / f"{name}.html"))\n'
        "    return robot, report"
    ),
    new_markdown_cell(
        "## 1. One shape\n"
        "A robot named `myfirst` with one link whose visual is a cylinder 0.6 m long and "
        "0.2 m in radius. `check` prints what `check_urdf` prints, then workbench's own "
        "findings: a link you can see but not touch has no collision geometry."
    ),
    new_code_cell('robot, report = step("myfirst")'),
    new_markdown_cell(
        "## 2. Multiple shapes\n"
        "A second link, `right_leg`, needs a joint to say where it is. Both shapes share the "
        "origin, so they overlap."
    ),
    new_code_cell('robot, report = step("multipleshapes")'),
    new_markdown_cell(
        "## 3. Origins\n"
        "The joint origin puts the leg 0.22 m to the right and 0.25 m up; the visual origin "
        "hangs the box 0.3 m below the joint and turns it upright (pitch pi/2)."
    ),
    new_code_cell(
        'robot, report = step("origins")\n'
        'print("right_leg in the world:", robot.forward_kinematics()["right_leg"].translation())'
    ),
    new_markdown_cell("## 4. Materials\nBlue body, white legs."),
    new_code_cell('robot, report = step("materials")\nprint(robot.materials)'),
    new_markdown_cell(
        "## 5. The finished model\n"
        "Feet, wheels, a gripper with finger meshes, and a head. The finger meshes are the "
        "project's own OBJ files, found through `package://workbench_urdf/meshes/...`."
    ),
    new_code_cell('robot, report = step("visual", show_file=not SHORT)\nprint(robot)'),
    new_markdown_cell(
        "## 6. Movable joints\n"
        "`flexible.urdf` makes the wheels and head continuous, the gripper pole prismatic "
        "and the fingers revolute. In the viewer, *Open Controls* shows one slider per joint "
        "(the joint_state_publisher GUI); `poll_sliders()` reads them and moves the robot."
    ),
    new_code_cell(
        "pose = {\n"
        '    "head_swivel": 0.8,\n'
        '    "gripper_extension": -0.2,\n'
        '    "left_gripper_joint": 0.4,\n'
        '    "right_gripper_joint": 0.4,\n'
        "}\n"
        'robot, report = step("flexible", q=pose, show_file=False)\n'
        "for joint in robot.movable_joints:\n"
        '    print(f"{joint.name:26s} {joint.type:11s} lower={joint.lower} upper={joint.upper}")\n'
        "viewer.add_joint_sliders(robot)\n"
        "viewer.poll_sliders()"
    ),
    new_markdown_cell(
        "The check above warns about every moving link without `<inertial>`: a simulator "
        "would treat them as massless. That is what the next step fixes.\n\n"
        "## 7. Collision and physical properties\n"
        "`physics.urdf` gives every link a `<collision>` (its visual geometry) and an "
        "`<inertial>`; base_link has the manual's 10 kg and inertia (0.4, 0.4, 0.2)."
    ),
    new_code_cell(
        'robot, report = step("physics", show_file=False)\n'
        "assert report.ok and not report.warnings\n"
        "for link in robot.links[:4]:\n"
        '    print(f"{link.name:18s} mass {link.mass} kg  collision: {link.has_collision}")'
    ),
    new_markdown_cell(
        "## 8. What the checker catches\n"
        "A link you write yourself, with a negative mass and an impossible inertia "
        "(one principal moment larger than the sum of the other two), saved as "
        "`broken.urdf` in the output folder:"
    ),
    new_code_cell(
        'broken = OUT / "broken.urdf"\n'
        'broken.write_text("""<?xml version="1.0"?>\n'
        '<robot name="broken">\n'
        '  <link name="base_link">\n'
        "    <inertial>\n"
        '      <mass value="-2"/>\n'
        '      <inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="5"/>\n'
        "    </inertial>\n"
        "  </link>\n"
        "</robot>\n"
        '""")\n'
        "report = check_robot(broken)\n"
        "print(report)\n"
        'assert [f.code for f in report.errors] == ["non-positive-mass", "inertia-triangle-inequality"]'
    ),
    new_markdown_cell(
        "## 9. A picture for your report\n"
        "Headless Chromium renders the last snapshot to `physics.png` in the output folder "
        "(skipped in the short test run)."
    ),
    new_code_cell(
        "if not SHORT:\n"
        '    png = viewer.render_png(OUT / "physics.html", OUT / "physics.png", width=640, height=480)\n'
        '    print("picture:", png)\n'
        "    display(Image(filename=str(png)))"
    ),
]
notebook = new_notebook(cells=cells)
notebook.metadata["kernelspec"] = {
    "display_name": "Python 3",
    "language": "python",
    "name": "python3",
}
notebook.metadata["language_info"] = {"name": "python"}
nbformat.validate(notebook)
nbformat.write(notebook, Path(__file__).resolve().parents[1] / "05_urdf.ipynb")
