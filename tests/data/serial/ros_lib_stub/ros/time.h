// Stand-in for the Arduino library's ros/time.h: the two fields messages use.
#ifndef WORKBENCH_TEST_ROS_TIME_H
#define WORKBENCH_TEST_ROS_TIME_H

#include <stdint.h>
#include "ros/duration.h"

namespace ros
{

class Time
{
public:
  uint32_t sec, nsec;
  Time() : sec(0), nsec(0) {}
};

}  // namespace ros

#endif
