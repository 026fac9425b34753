// Round trip through generated ros_lib headers, driven by tests/serial/test_make_libraries.py.
//
// The test writes "entries.inc": an #include for every generated header and the table
// ENTRIES of every message class. Each line on stdin is "NAME HEX" (HEX "-" when empty):
// the object of class NAME (one per class, kept between lines, as a board keeps its
// messages) deserializes the bytes and serializes itself again. Each output line is
//   NAME getType() getMD5() BYTES_CONSUMED HEX_WRITTEN[|field=value...]
// with the fields of a few classes printed so the test can compare values, not only bytes.

#include <stdio.h>

#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "ros/msg.h"

struct Entry
{
  const char *name;
  ros::Msg *(*make)();
};

#include "entries.inc"

namespace
{

std::string format(const char *spec, double value)
{
  char text[64];
  snprintf(text, sizeof(text), spec, value);
  return text;
}

std::string num(double value) { return format("%.9g", value); }

class Fields
{
public:
  Fields &add(const std::string &name, const std::string &value)
  {
    out_ << "|" << name << "=" << value;
    return *this;
  }
  Fields &add(const std::string &name, double value) { return add(name, num(value)); }
  template <typename T>
  Fields &list(const std::string &name, const T *values, uint32_t length)
  {
    std::string text;
    for (uint32_t i = 0; i < length; ++i)
      text += (i ? "," : "") + num(values[i]);
    return add(name, text);
  }
  std::string str() const { return out_.str(); }

private:
  std::ostringstream out_;
};

void header(Fields &f, const std_msgs::Header &h)
{
  f.add("header.seq", h.seq).add("header.stamp", num(h.stamp.sec) + "." + num(h.stamp.nsec));
  f.add("header.frame_id", h.frame_id);
}

void sample(Fields &f, const std::string &prefix, const lab_serial_msgs::Sample &s)
{
  f.add(prefix + ".id", s.id).list(prefix + ".values", s.values, s.values_length);
  f.add(prefix + ".grade", s.grade);
}

std::string describe(ros::Msg *msg)
{
  Fields f;
  if (std_msgs::String *m = dynamic_cast<std_msgs::String *>(msg))
    f.add("data", m->data);
  else if (std_msgs::Bool *m = dynamic_cast<std_msgs::Bool *>(msg))
    f.add("data", m->data ? 1 : 0);
  else if (std_msgs::Duration *m = dynamic_cast<std_msgs::Duration *>(msg))
    f.add("data.sec", m->data.sec).add("data.nsec", m->data.nsec);
  else if (geometry_msgs::Twist *m = dynamic_cast<geometry_msgs::Twist *>(msg))
    f.add("linear", num(m->linear.x) + "," + num(m->linear.y) + "," + num(m->linear.z))
        .add("angular", num(m->angular.x) + "," + num(m->angular.y) + "," + num(m->angular.z));
  else if (sensor_msgs::LaserScan *m = dynamic_cast<sensor_msgs::LaserScan *>(msg))
  {
    header(f, m->header);
    f.add("angle_min", m->angle_min).add("angle_max", m->angle_max);
    f.add("range_max", m->range_max);
    f.list("ranges", m->ranges, m->ranges_length);
    f.list("intensities", m->intensities, m->intensities_length);
  }
  else if (lab_serial_msgs::Reading *m = dynamic_cast<lab_serial_msgs::Reading *>(msg))
  {
    header(f, m->header);
    f.add("level", m->level).add("count", std::to_string(m->count));
    f.add("value", m->value).list("gains", m->gains, 3).list("deltas", m->deltas, m->deltas_length);
    f.list("switches", m->switches, 2).add("label", m->label);
    std::string tags;
    for (uint32_t i = 0; i < m->tags_length; ++i)
      tags += std::string(i ? "," : "") + m->tags[i];
    f.add("tags", tags);
    f.add("stamp", num(m->stamp.sec) + "." + num(m->stamp.nsec));
    f.add("period", num(m->period.sec) + "." + num(m->period.nsec));
    std::string waits;
    for (uint32_t i = 0; i < m->waits_length; ++i)
      waits += (i ? "," : "") + num(m->waits[i].sec) + "." + num(m->waits[i].nsec);
    f.add("waits", waits);
    sample(f, "latest", m->latest);
    f.add("history", m->history_length);
    for (uint32_t i = 0; i < m->history_length; ++i)
      sample(f, "history" + std::to_string(i), m->history[i]);
    sample(f, "pair0", m->pair[0]);
    sample(f, "pair1", m->pair[1]);
    f.add("LOW", lab_serial_msgs::Reading::LOW).add("HIGH", lab_serial_msgs::Reading::HIGH);
    f.add("SCALE", lab_serial_msgs::Reading::SCALE).add("UNIT", lab_serial_msgs::Reading::UNIT);
  }
  return f.str();
}

std::vector<unsigned char> from_hex(const std::string &hex)
{
  std::vector<unsigned char> bytes;
  if (hex == "-")
    return bytes;
  for (size_t i = 0; i + 1 < hex.size(); i += 2)
    bytes.push_back((unsigned char)std::stoul(hex.substr(i, 2), nullptr, 16));
  return bytes;
}

std::string to_hex(const unsigned char *bytes, int length)
{
  static const char digits[] = "0123456789abcdef";
  std::string hex = length ? "" : "-";
  for (int i = 0; i < length; ++i)
  {
    hex += digits[bytes[i] >> 4];
    hex += digits[bytes[i] & 15];
  }
  return hex;
}

}  // namespace

int main()
{
  std::map<std::string, ros::Msg *(*)()> factories;
  for (const Entry &entry : ENTRIES)
    factories[entry.name] = entry.make;
  std::map<std::string, ros::Msg *> objects;
  // Received strings point into their receive buffer, as on the board: keep every buffer.
  std::vector<std::vector<unsigned char> *> buffers;
  std::string name, hex;
  while (std::cin >> name >> hex)
  {
    if (!factories.count(name))
    {
      std::cout << name << " unknown" << std::endl;
      continue;
    }
    if (!objects.count(name))
      objects[name] = factories[name]();
    ros::Msg *msg = objects[name];
    std::vector<unsigned char> *in = new std::vector<unsigned char>(from_hex(hex));
    in->resize(in->size() + 1);  // never empty, so data() is a valid buffer
    buffers.push_back(in);
    int consumed = msg->deserialize(in->data());
    std::vector<unsigned char> out(4 * in->size() + 65536);
    int written = msg->serialize(out.data());
    std::cout << name << " " << msg->getType() << " " << msg->getMD5() << " " << consumed << " "
              << to_hex(out.data(), written) << describe(msg) << std::endl;
  }
  return 0;
}
