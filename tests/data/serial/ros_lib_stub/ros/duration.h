// Stand-in for the Arduino library's ros/duration.h: the two fields messages use.
#ifndef WORKBENCH_TEST_ROS_DURATION_H
#define WORKBENCH_TEST_ROS_DURATION_H

#include <stdint.h>

namespace ros
{

class Duration
{
public:
  int32_t sec, nsec;
  Duration() : sec(0), nsec(0) {}
};

}  // namespace ros

#endif
