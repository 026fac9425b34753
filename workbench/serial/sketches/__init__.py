"""The sketches a virtual board can run (``workbench serial virtual NAME``).

Each is a Python translation, line by line, of an Arduino sketch written against
ros_lib: ``setup()`` and ``loop()`` as in the ``.ino`` file, ``nh = ros.NodeHandle()``
for ``ros::NodeHandle nh;`` and so on (see :mod:`workbench.serial.device`). A
sketch may say how the board is wired with ``WIRING``: ``{"button": 7, "motor": 13}``
names the push buttons (inputs pressed from the terminal or a topic) and the
outputs (printed and published when they change).

* ``hello_world``: the manual's program A, "hello world!" on ``chatter`` every second;
* ``button_motor``: the manual's program B, a button on pin 7 published as
  ``pushed`` and driving the motor on pin 13;
* ``toggle_led``: a subscriber, ``toggle_led`` (std_msgs/Empty) toggles the LED;
* ``service_param``: a service server (``led``, std_srvs/SetBool), a service
  client (``greeting``, std_srvs/Trigger) and a parameter (``~greeting_period``).
"""
