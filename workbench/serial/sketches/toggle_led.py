"""rosserial Subscriber Example: ``toggle_led`` (std_msgs/Empty) toggles the LED on pin 13.

ros_lib's "Blink" example, line by line::

    ros::NodeHandle nh;
    void messageCb( const std_msgs::Empty& toggle_msg){
      digitalWrite(13, HIGH-digitalRead(13));   // blink the led
    }
    ros::Subscriber<std_msgs::Empty> sub("toggle_led", &messageCb );
    void setup() { pinMode(13, OUTPUT); nh.initNode(); nh.subscribe(sub); }
    void loop() { nh.spinOnce(); delay(1); }

Try it: ``workbench topic pub -1 toggle_led std_msgs/Empty``.
"""

from workbench.msgs.std_msgs import Empty
from workbench.serial import device as ros
from workbench.serial.arduino import HIGH, OUTPUT, delay, digitalRead, digitalWrite, pinMode

WIRING = {"led": 13}

nh = ros.NodeHandle()


def messageCb(toggle_msg):  # noqa: N802 - the example's name
    digitalWrite(13, HIGH - digitalRead(13))  # blink the led


sub = ros.Subscriber("toggle_led", Empty, messageCb)


def setup():
    pinMode(13, OUTPUT)
    nh.initNode()
    nh.subscribe(sub)


def loop():
    nh.spinOnce()
    delay(1)
