"""rosserial Publisher Example: prints "hello world!" (Experiment 11, program A).

The manual's sketch, line by line::

    #include <ros.h>
    #include <std_msgs/String.h>
    ros::NodeHandle nh;
    std_msgs::String str_msg;
    ros::Publisher chatter("chatter", &str_msg);
    char hello[13] = "hello world!";
    void setup() { nh.initNode(); nh.advertise(chatter); }
    void loop() {
      str_msg.data = hello;
      chatter.publish( &str_msg );
      nh.spinOnce();
      delay(1000);
    }
"""

from workbench.msgs.std_msgs import String
from workbench.serial import device as ros
from workbench.serial.arduino import delay

nh = ros.NodeHandle()

str_msg = String()
chatter = ros.Publisher("chatter", str_msg)

hello = "hello world!"


def setup():
    nh.initNode()
    nh.advertise(chatter)


def loop():
    str_msg.data = hello
    chatter.publish(str_msg)
    nh.spinOnce()
    delay(1000)
