#pragma once
// What a scene file says, in SI units, with no file format attached. The XML reader
// fills it; the scene compiler turns it into collision geometry. Nothing here loads
// meshes or knows about XML.

#include "geometry/object_dynamics.h"
#include "geometry/object_motion.h"
#include "geometry/pose.h"
#include "geometry/touchable_faces.h"
#include "material/haptic_material.h"
#include "diagnostics/diagnostic.h"
#include "scene/plugin_kind.h"

#include <Eigen/Core>

#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace mhd {

struct MeshSource {
  std::filesystem::path file;  ///< absolute (resolved against the XML file that named it)
  /// Multiplies mesh-file coordinates into metres: the scene's unit (0.001 for mm)
  /// times the object's scale, per axis.
  Eigen::Vector3d scale_to_m = Eigen::Vector3d::Ones();
};

// `exact`: the proxy touches the shape itself, not its tessellation (docs/proxy.md, "Exact
// primitives"); the tessellation stays for display. An exact plane is the infinite
// half-space below it (z <= 0 in the object's frame), its size only what is drawn.
struct PlaneSource { double size_x_m = 0, size_y_m = 0; bool exact = false; };
struct SphereSource { double radius_m = 0; int subdivisions = 4; bool exact = false; };
struct BoxSource { Eigen::Vector3d size_m = Eigen::Vector3d::Zero(); bool exact = false; };
struct CylinderSource { double radius_m = 0, height_m = 0; int segments = 64; bool exact = false; };
/// Along z: `length_m` of cylinder between the centres of its two hemispherical caps.
struct CapsuleSource { double radius_m = 0, length_m = 0; int segments = 32; bool exact = true; };

using ShapeSource = std::variant<MeshSource, PlaneSource, SphereSource, BoxSource, CylinderSource, CapsuleSource>;

struct ObjectDescription {
  std::string name;
  ShapeSource shape;
  Pose X_WO = Pose::Identity();  ///< pose of the object in the world
  std::string material_name;      ///< empty for an inline material
  HapticMaterial material;        ///< resolved (named or inline)
  /// Scripted motion (<motion>); none for a still object. X_WO is then its pose at t = 0.
  std::optional<ObjectMotion> motion;
  /// Mass and friction (<dynamics>): a body the hand can push; none for a still or
  /// scripted object (an object has a motion or dynamics, not both).
  std::optional<ObjectDynamics> dynamics;
  /// touchable="front|back|both": which side of its triangles the hand can touch.
  TouchableFaces touchable = TouchableFaces::Both;
  SourceLocation where;
};

/// A rig frame: the pose of `name` in its `parent` frame.
struct FrameDescription {
  std::string name;
  std::string parent;
  Pose X_PF = Pose::Identity();
  SourceLocation where;
};

/// A vertical lift between the robot and the arm (<rig><lift .../>): a prismatic joint
/// along the robot frame's z (up), whose height 0 is where the rig's "phantom" frame puts
/// the arm. Heights, speed and acceleration in SI units.
struct LiftDescription {
  double min_m = 0.0;  ///< the lowest height, <= 0
  double max_m = 0.0;  ///< the highest, >= 0 and > min_m
  double max_speed_mps = 0.0;
  double max_acceleration_mps2 = 0.0;
  SourceLocation where;
};

/// What carries the device (docs/desktop.md). Mobile: the POSTECH rig, a tracker, a base
/// and a planner (the frames of scenes/rigs/pomhi.xml). Desktop: a device fixed in the
/// world and nothing else; the <rig> holds one frame, "device", parent "world".
enum class RigKind { Mobile, Desktop };

/// The rig's kind as the scene declares it (<rig kind="...">; mobile when no <rig> says).
struct RigKindDeclaration {
  RigKind kind = RigKind::Mobile;
  std::optional<SourceLocation> where;  ///< the <rig kind="..."> that said so; empty: the default
};

struct PluginDescription {
  PluginKind kind = PluginKind::Device;
  std::string name;                           ///< plugin name, e.g. "sim_phantom"
  std::map<std::string, std::string> params;  ///< passed to the plugin's open()
  SourceLocation where;
};

/// An object several rigs share (<sharing><shared_object>, docs/shared-objects.md): one
/// rig at a time (its authority) runs its physics; the others render its state.
struct SharedObjectDescription {
  std::string object;               ///< the <object name> shared; a pushable one
  std::uint32_t id = 0;             ///< what the link carries: the same in every rig's scene
  std::vector<std::uint32_t> rigs;  ///< the rigs that may hold its authority; rigs[0] holds it first
  SourceLocation where;
};

/// <sharing rig_id="N">: this rig's id among the rigs sharing objects, and those objects.
struct SharingDescription {
  std::uint32_t rig_id = 0;
  bool rig_id_read = true;  ///< false: rig_id was missing or bad (reported), nothing is judged by it
  std::vector<SharedObjectDescription> objects;
  SourceLocation where;
};

/// A block of named settings for an engine part that reads its own parameters (the
/// simulated user, the base planner, the haptic server): <simulated_user>, <planner
/// kind="...">, <server>, each holding <param name="..." value="..."/>. The part checks the
/// names and values itself and reports errors against `param_where`.
struct ParamBlock {
  std::string kind;  ///< the kind="..." attribute where the element has one, else empty
  std::map<std::string, std::string> params;
  std::map<std::string, SourceLocation> param_where;  ///< each param's line
  SourceLocation where;                               ///< the element
};

struct HapticsSettings {
  /// <haptics max_force_N>: a clamp that may only lower the device's own limit. Absent:
  /// the device's limit, the one source of it (docs/haptic_server.md, "Force limit").
  std::optional<double> max_force_N;
  double update_rate_Hz = 1000.0;
};

/// The clamp of tools that run the proxy with no device open (proxy-replay, strokes, the
/// stress tools, `mhd try`) when the scene gives no <haptics max_force_N>: the peak of a
/// PHANToM Premium 1.5, the thesis's arm. A run with a device never uses it.
inline constexpr double kNoDeviceMaxForce_N = 8.5;

/// Default of <scene max_triangles>: the most triangles a scene may load.
inline constexpr std::uint64_t kDefaultMaxTriangles = 50'000'000;

struct SceneDescription {
  std::filesystem::path file;  ///< the root XML file
  std::string name;
  /// Triangles over the scene's distinct meshes and primitives, at most; checked against
  /// each mesh file's header before it is loaded, and after.
  std::uint64_t max_triangles = kDefaultMaxTriangles;
  HapticsSettings haptics;
  std::map<std::string, HapticMaterial> materials;
  std::vector<ObjectDescription> objects;
  std::vector<FrameDescription> rig_frames;
  RigKindDeclaration rig_kind;
  std::optional<LiftDescription> rig_lift;  ///< <rig><lift>: none, the arm at a fixed height
  std::vector<PluginDescription> plugins;
  SourceLocation plugins_where;  ///< the first <plugins>; empty file when there is none
  std::optional<ParamBlock> simulated_user;  ///< <simulated_user>: who drives simulated hardware
  std::optional<ParamBlock> planner;         ///< <planner kind="...">: the base's motion planner
  std::optional<ParamBlock> server;          ///< <server>: haptic server rates, sensors, safety limits
  std::optional<SharingDescription> sharing;  ///< <sharing>: objects shared with other rigs
};

}  // namespace mhd
