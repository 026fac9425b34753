// Loads one SDFormat file with libsdformat (sdf::Root::Load) and prints, as one JSON
// object, the errors it reports and the worlds, models, links and joints it sees: each
// model's pose in its parent (the world or the enclosing model), each link's pose in its
// model, each joint's links, type and first axis in its model's frame.
// model:// URIs are looked up in GAZEBO_MODEL_PATH, as Gazebo does.
// Build: g++ sdformat_check.cc $(pkg-config --cflags --libs sdformat12) -o sdformat_check
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>

#include <sdf/sdf.hh>

namespace {

std::string Quoted(const std::string &text) {
  std::ostringstream out;
  out << '"';
  for (const unsigned char c : text) {
    if (c == '"' || c == '\\') {
      out << '\\' << c;
    } else if (c < 0x20) {
      char buffer[8];
      std::snprintf(buffer, sizeof(buffer), "\\u%04x", c);
      out << buffer;
    } else {
      out << c;
    }
  }
  out << '"';
  return out.str();
}

std::string PoseJson(const ignition::math::Pose3d &pose) {
  std::ostringstream out;
  out.precision(17);
  const auto euler = pose.Rot().Euler();
  out << '[' << pose.Pos().X() << ',' << pose.Pos().Y() << ',' << pose.Pos().Z() << ','
      << euler.X() << ',' << euler.Y() << ',' << euler.Z() << ']';
  return out.str();
}

// `pose` is the model's pose in `parent_frame` (empty: the pose the file gives it).
std::string ModelJson(const sdf::Model &model, const std::string &parent_frame) {
  std::ostringstream out;
  out.precision(17);
  ignition::math::Pose3d pose = model.RawPose();
  if (!parent_frame.empty()) {
    model.SemanticPose().Resolve(pose, parent_frame);
  }
  out << "{\"name\":" << Quoted(model.Name()) << ",\"static\":"
      << (model.Static() ? "true" : "false") << ",\"pose\":" << PoseJson(pose)
      << ",\"canonical_link\":" << Quoted(model.CanonicalLinkName()) << ",\"links\":[";
  for (uint64_t i = 0; i < model.LinkCount(); ++i) {
    const sdf::Link *link = model.LinkByIndex(i);
    ignition::math::Pose3d link_pose;
    link->SemanticPose().Resolve(link_pose, "__model__");
    out << (i ? "," : "") << "{\"name\":" << Quoted(link->Name())
        << ",\"pose\":" << PoseJson(link_pose) << '}';
  }
  out << "],\"joints\":[";
  for (uint64_t i = 0; i < model.JointCount(); ++i) {
    const sdf::Joint *joint = model.JointByIndex(i);
    out << (i ? "," : "") << "{\"name\":" << Quoted(joint->Name())
        << ",\"parent\":" << Quoted(joint->ParentLinkName())
        << ",\"child\":" << Quoted(joint->ChildLinkName())
        << ",\"type\":" << static_cast<int>(joint->Type()) << ",\"axis\":";
    const sdf::JointAxis *axis = joint->Axis(0);
    ignition::math::Vector3d xyz;
    if (axis != nullptr && axis->ResolveXyz(xyz, "__model__").empty()) {
      out << '[' << xyz.X() << ',' << xyz.Y() << ',' << xyz.Z() << ']';
    } else {
      out << "null";
    }
    out << '}';
  }
  out << "],\"models\":[";
  for (uint64_t i = 0; i < model.ModelCount(); ++i) {
    out << (i ? "," : "") << ModelJson(*model.ModelByIndex(i), "__model__");
  }
  out << "]}";
  return out.str();
}

}  // namespace

int main(int argc, char **argv) {
  if (argc != 2) {
    std::cerr << "usage: sdformat_check FILE\n";
    return 2;
  }
  sdf::ParserConfig config;
  if (const char *paths = std::getenv("GAZEBO_MODEL_PATH")) {
    config.AddURIPath("model://", paths);
  }
  sdf::Root root;
  const sdf::Errors errors = root.Load(argv[1], config);
  std::ostringstream out;
  out << "{\"version\":" << Quoted(root.Version()) << ",\"errors\":[";
  for (size_t i = 0; i < errors.size(); ++i) {
    const auto line = errors[i].LineNumber();
    out << (i ? "," : "") << "{\"code\":" << static_cast<int>(errors[i].Code())
        << ",\"message\":" << Quoted(errors[i].Message())
        << ",\"line\":" << (line ? std::to_string(*line) : "null") << '}';
  }
  out << "],\"worlds\":[";
  for (uint64_t w = 0; w < root.WorldCount(); ++w) {
    const sdf::World *world = root.WorldByIndex(w);
    out << (w ? "," : "") << "{\"name\":" << Quoted(world->Name()) << ",\"models\":[";
    for (uint64_t m = 0; m < world->ModelCount(); ++m) {
      out << (m ? "," : "") << ModelJson(*world->ModelByIndex(m), "world");
    }
    out << "]}";
  }
  out << "],\"model\":";
  out << (root.Model() != nullptr ? ModelJson(*root.Model(), "") : "null");
  out << "}\n";
  std::cout << out.str();
  return 0;
}
