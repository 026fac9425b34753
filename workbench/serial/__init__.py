"""rosserial: an Arduino (or any rosserial device) on the bus over a serial port or TCP.

* :mod:`~workbench.serial.protocol` and :mod:`~workbench.serial.framing`: the wire
  format and a decoder that resynchronises on any damage;
* :mod:`~workbench.serial.bridge` and :mod:`~workbench.serial.serial_node`: the host
  (rosserial_python's ``serial_node.py``), :mod:`~workbench.serial.links` its ports;
* :mod:`~workbench.serial.device`, :mod:`~workbench.serial.arduino`,
  :mod:`~workbench.serial.board` and :mod:`~workbench.serial.virtual`: ros_lib's
  device side in Python and a virtual board on a pseudo-terminal running the
  sketches of :mod:`workbench.serial.sketches`;
* :mod:`~workbench.serial.make_libraries`: rosserial_arduino's ``make_libraries.py``,
  Arduino headers (``ros_lib``) for every message type workbench knows.

pyserial is imported only where a port is opened.
"""
