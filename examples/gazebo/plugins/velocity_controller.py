"""A plugin that talks to ROS: the Velodyne tutorial's joint velocity controller.

::

    <plugin name="velodyne_control" filename="velocity_controller.py">
      <joint>top_joint</joint>        <!-- default: the model's first joint -->
      <velocity>0</velocity>          <!-- initial target, rad/s -->
      <topic>/my_velodyne/vel_cmd</topic>  <!-- default: /<model>/vel_cmd -->
      <p_gain>0.1</p_gain> <i_gain>0.0</i_gain>
    </plugin>

It subscribes to ``std_msgs/Float32`` on the topic and drives the joint to that
velocity with a PI controller on the joint's effort (N m), like the tutorial's
``JointController::SetVelocityTarget``. Try it with::

    workbench topic pub /my_velodyne/vel_cmd std_msgs/Float32 "data: 2.0"
"""

from workbench.sim.plugins import ModelPlugin


class VelocityController(ModelPlugin):
    """Hold a joint at a velocity target that comes from a topic."""

    def load(self, model, sdf, node):
        self.model = model
        self.joint = sdf.get("joint") or model.joint_names[0]
        self.target = sdf.get("velocity", 0.0)
        self.p_gain = sdf.get("p_gain", 0.1)
        self.i_gain = sdf.get("i_gain", 0.0)
        self.integral = 0.0
        topic = sdf.get("topic") or f"/{model.name}/vel_cmd"
        if node is not None:
            node.create_subscription(topic, "std_msgs/Float32", self.on_command)

    def on_command(self, message):
        self.target = float(message.data)

    def update(self, info):
        error = self.target - self.model.joint_velocity(self.joint)
        self.integral += error * info.dt
        effort = self.p_gain * error + self.i_gain * self.integral
        self.model.set_joint_effort(self.joint, effort)
