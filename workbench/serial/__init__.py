"""rosserial: an Arduino on the bus over a serial port."""
