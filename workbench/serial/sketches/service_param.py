"""Services both ways and a parameter: what ros_lib's ServiceServer, ServiceClient and getParam do.

* the board offers the service ``led`` (std_srvs/SetBool): ``workbench service call
  /led "data: true"`` switches the LED on pin 13 and answers ``success: True``;
* it calls the bus service ``greeting`` (std_srvs/Trigger) every
  ``~greeting_period`` milliseconds (the host node's private parameter, read once
  with ``nh.getParam``; 2000 when it is not set) and publishes the answer's
  ``message`` on ``greetings`` (std_msgs/String), logging it with ``nh.loginfo``.

In C++ the same sketch reads::

    ros::NodeHandle nh;
    void ledCb(const std_srvs::SetBool::Request& req, std_srvs::SetBool::Response& res) {
      digitalWrite(LED_BUILTIN, req.data ? HIGH : LOW);
      res.success = true; res.message = req.data ? "LED on" : "LED off";
    }
    ros::ServiceServer<std_srvs::SetBool::Request, std_srvs::SetBool::Response> server("led", &ledCb);
    ros::ServiceClient<std_srvs::Trigger::Request, std_srvs::Trigger::Response> client("greeting");
    std_msgs::String str_msg;
    ros::Publisher greetings("greetings", &str_msg);
    int period[1] = {2000};
    unsigned long last = 0;
    void setup() {
      pinMode(LED_BUILTIN, OUTPUT);
      nh.initNode(); nh.advertiseService(server); nh.serviceClient(client); nh.advertise(greetings);
      while (!nh.connected()) { nh.spinOnce(); delay(1); }
      if (!nh.getParam("~greeting_period", period, 1)) nh.loginfo("greeting every 2000 ms");
    }
    void loop() {
      if (millis() - last >= period[0]) {
        last = millis();
        std_srvs::Trigger::Request req; std_srvs::Trigger::Response res;
        client.call(req, res);
        str_msg.data = res.message; greetings.publish(&str_msg); nh.loginfo(res.message);
      }
      nh.spinOnce(); delay(1);
    }
"""

from workbench.msgs.std_msgs import String
from workbench.msgs.std_srvs import SetBool, Trigger
from workbench.serial import device as ros
from workbench.serial.arduino import (
    HIGH,
    LED_BUILTIN,
    LOW,
    OUTPUT,
    delay,
    digitalWrite,
    millis,
    pinMode,
)

WIRING = {"led": LED_BUILTIN}

nh = ros.NodeHandle()


def ledCb(req, res):  # noqa: N802
    digitalWrite(LED_BUILTIN, HIGH if req.data else LOW)
    res.success = True
    res.message = "LED on" if req.data else "LED off"


server = ros.ServiceServer("led", SetBool, ledCb)
client = ros.ServiceClient("greeting", Trigger)
str_msg = String()
greetings = ros.Publisher("greetings", str_msg)
period = [2000]
last = 0


def setup():
    pinMode(LED_BUILTIN, OUTPUT)
    nh.initNode()
    nh.advertiseService(server)
    nh.serviceClient(client)
    nh.advertise(greetings)
    while not nh.connected():
        nh.spinOnce()
        delay(1)
    if not nh.getParam("~greeting_period", period, 1):
        nh.loginfo("greeting every 2000 ms")


def loop():
    global last
    if millis() - last >= period[0]:
        last = millis()
        req = Trigger.Request()
        res = Trigger.Response()
        client.call(req, res)
        str_msg.data = res.message
        greetings.publish(str_msg)
        nh.loginfo(res.message)
    nh.spinOnce()
    delay(1)
