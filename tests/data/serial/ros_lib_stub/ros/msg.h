// Stand-in for the Arduino library's ros/msg.h, so that generated message headers
// compile and run on a PC in the tests: the base class and the helpers they call.
#ifndef WORKBENCH_TEST_ROS_MSG_H
#define WORKBENCH_TEST_ROS_MSG_H

#include <stdint.h>
#include <stddef.h>
#include <string.h>

namespace ros
{

class Msg
{
public:
  virtual ~Msg() {}
  virtual int serialize(unsigned char *outbuffer) const = 0;
  virtual int deserialize(unsigned char *inbuffer) = 0;
  virtual const char *getType() = 0;
  virtual const char *getMD5() = 0;

  // float64 on the wire, float on the board: widened to a double, eight bytes little-endian.
  static int serializeAvrFloat64(unsigned char *outbuffer, const float value)
  {
    const double wide = value;
    uint64_t bits;
    memcpy(&bits, &wide, sizeof(bits));
    for (int b = 0; b < 8; ++b)
      outbuffer[b] = (unsigned char)(bits >> (8 * b));
    return 8;
  }

  // Eight little-endian bytes of a double, narrowed to the nearest float.
  static int deserializeAvrFloat64(const unsigned char *inbuffer, float *value)
  {
    uint64_t bits = 0;
    for (int b = 0; b < 8; ++b)
      bits |= (uint64_t)inbuffer[b] << (8 * b);
    double wide;
    memcpy(&wide, &bits, sizeof(wide));
    *value = (float)wide;
    return 8;
  }

  // An unsigned integer into sizeof(V) bytes, least significant first.
  template <typename A, typename V>
  static void varToArr(A arr, const V var)
  {
    for (size_t b = 0; b < sizeof(V); ++b)
      arr[b] = (unsigned char)(var >> (8 * b));
  }

  // sizeof(V) bytes, least significant first, into an unsigned integer.
  template <typename V, typename A>
  static void arrToVar(V &var, const A arr)
  {
    var = 0;
    for (size_t b = 0; b < sizeof(V); ++b)
      var |= (V)((V)arr[b] << (8 * b));
  }
};

}  // namespace ros

#endif
