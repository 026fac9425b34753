"""A button switch drives a DC motor and is published as ``pushed`` (Experiment 11, program B).

The hardware of step 1: a push button from pin 7 to ground, the motor driver on
pin 13. The manual's sketch, line by line (``!digitalRead`` becomes ``not
digitalRead``, the globals a function assigns are declared ``global``)::

    ros::NodeHandle nh;
    std_msgs::Bool pushed_msg;
    ros::Publisher pub_button("pushed", &pushed_msg);
    const int button_pin = 7;
    const int motor_pin = 13;
    bool last_reading;
    long last_debounce_time=0;
    long debounce_delay=50;
    bool published = true;
    void setup() {
      nh.initNode();
      nh.advertise(pub_button);
      pinMode(motor_pin, OUTPUT);
      pinMode(button_pin, INPUT);
      digitalWrite(button_pin, HIGH);      // enable the pull-up resistor
      last_reading = ! digitalRead(button_pin);
    }
    void loop() {
      bool reading = ! digitalRead(button_pin);
      if (last_reading!= reading){ last_debounce_time = millis(); published = false; }
      if ( !published && (millis() - last_debounce_time) > debounce_delay) {
        digitalWrite(motor_pin, reading);
        pushed_msg.data = reading;
        pub_button.publish(&pushed_msg);
        published = true;
      }
      last_reading = reading;
      nh.spinOnce();
    }
"""

from workbench.msgs.std_msgs import Bool
from workbench.serial import device as ros
from workbench.serial.arduino import HIGH, INPUT, OUTPUT, digitalRead, digitalWrite, millis, pinMode

WIRING = {"button": 7, "motor": 13}

nh = ros.NodeHandle()

pushed_msg = Bool()
pub_button = ros.Publisher("pushed", pushed_msg)

button_pin = 7
motor_pin = 13

last_reading = False
last_debounce_time = 0
debounce_delay = 50
published = True


def setup():
    global last_reading
    nh.initNode()
    nh.advertise(pub_button)

    # initialize an motor output pin
    # and a input pin for our push button
    pinMode(motor_pin, OUTPUT)
    pinMode(button_pin, INPUT)

    # Enable the pullup resistor on the button
    digitalWrite(button_pin, HIGH)

    last_reading = not digitalRead(button_pin)


def loop():
    global last_reading, last_debounce_time, published
    reading = not digitalRead(button_pin)

    if last_reading != reading:
        last_debounce_time = millis()
        published = False

    # if the button value has not changed for the debounce delay, we know its stable
    if not published and (millis() - last_debounce_time) > debounce_delay:
        digitalWrite(motor_pin, reading)
        pushed_msg.data = reading
        pub_button.publish(pushed_msg)
        published = True

    last_reading = reading

    nh.spinOnce()
