// The god-object proxy from Python: a Proxy on a compiled scene is stepped over an (N, 3)
// array of HIP positions, one step_proxy per row, exactly as `mhd proxy-replay` steps it
// (no plugins, no safety stage, no threads), and answers with arrays: proxy, force,
// contact. The loop runs without the GIL and writes straight into the NumPy buffers.

#include "bindings.h"
#include "scene_handles.h"

#include "proxy/god_object.h"
#include "proxy/proxy_start.h"

#include <fmt/core.h>
#include <pybind11/numpy.h>

#include <cmath>
#include <cstdint>
#include <mutex>
#include <string>
#include <utility>

namespace py = pybind11;

namespace mhd::python {
namespace {

using InputArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// A point given as 3 numbers (a list, a tuple or a (3,) array).
Eigen::Vector3d point3(const InputArray& p, const char* name) {
  if (p.ndim() != 1 || p.shape(0) != 3) throw py::value_error(std::string(name) + " must have shape (3,)");
  const Eigen::Vector3d v(p.data()[0], p.data()[1], p.data()[2]);
  if (!v.allFinite()) throw py::value_error(fmt::format("{} = ({}, {}, {}) is not finite", name, v.x(), v.y(), v.z()));
  return v;
}

/// What N steps did, one row per step.
struct ProxyTrace {
  py::array_t<double> proxy_W_m;           ///< (N, 3)
  py::array_t<double> force_W_N;           ///< (N, 3), clamped to the scene's max_force_N
  py::array_t<bool> contact;               ///< (N,)
  py::array_t<std::int32_t> planes;        ///< (N,) constraint planes at the end of the step
  py::array_t<std::int32_t> contact_object;  ///< (N,) object of the first plane, -1 without contact
  py::array_t<bool> budget_exhausted;      ///< (N,) the step ran out of its work budget
};

class Proxy {
 public:
  Proxy(CompiledSceneHandle scene, const InputArray& p_W_hip_m) : scene_(std::move(scene)) { reset(p_W_hip_m); }

  void reset(const InputArray& p_W_hip) {
    const Eigen::Vector3d p_W_hip_m = point3(p_W_hip, "p_W_hip_m");
    const CompiledScene& scene = *scene_.compiled;
    if (const auto why = proxy_start_blocked(scene.world, p_W_hip_m, scene.proxy.skin_m)) {
      throw py::value_error(fmt::format("the HIP ({}, {}, {}) m {} in {}; the proxy must start in free space",
                                        p_W_hip_m.x(), p_W_hip_m.y(), p_W_hip_m.z(), *why,
                                        scene_.description->file.string()));
    }
    const std::lock_guard lock(mutex_);
    reset_proxy(state_, p_W_hip_m);
  }

  ProxyTrace step(const InputArray& p_W_hip_m, const InputArray& dt_s) {
    if (p_W_hip_m.ndim() != 2 || p_W_hip_m.shape(1) != 3) {
      throw py::value_error("p_W_hip_m must have shape (N, 3)");
    }
    const py::ssize_t n = p_W_hip_m.shape(0);
    const bool dt_per_row = dt_s.ndim() == 1;
    if (!(dt_s.ndim() == 0 || (dt_per_row && dt_s.shape(0) == n))) {
      throw py::value_error("dt_s must be a number or have shape (N,) like p_W_hip_m's rows");
    }
    const double* hip = p_W_hip_m.data();
    // A NaN or infinite HIP would be stepped as a position: refuse the whole array, naming
    // the first such row, before any step changes the proxy.
    for (py::ssize_t k = 0; k < n; ++k) {
      const double* row = hip + 3 * k;
      if (!(std::isfinite(row[0]) && std::isfinite(row[1]) && std::isfinite(row[2]))) {
        throw py::value_error(
            fmt::format("p_W_hip_m[{}] = ({}, {}, {}) is not finite", k, row[0], row[1], row[2]));
      }
    }
    const double* dt = dt_s.data();
    for (py::ssize_t k = 0; k < (dt_per_row ? n : 1); ++k) {
      if (!(std::isfinite(dt[k]) && dt[k] > 0.0)) {
        throw py::value_error(fmt::format("dt_s{} = {} must be finite and > 0",
                                          dt_per_row ? fmt::format("[{}]", k) : std::string(), dt[k]));
      }
    }
    ProxyTrace trace{py::array_t<double>({n, py::ssize_t{3}}), py::array_t<double>({n, py::ssize_t{3}}),
                     py::array_t<bool>(n), py::array_t<std::int32_t>(n), py::array_t<std::int32_t>(n),
                     py::array_t<bool>(n)};
    double* proxy = trace.proxy_W_m.mutable_data();
    double* force = trace.force_W_N.mutable_data();
    bool* contact = trace.contact.mutable_data();
    std::int32_t* planes = trace.planes.mutable_data();
    std::int32_t* object = trace.contact_object.mutable_data();
    bool* exhausted = trace.budget_exhausted.mutable_data();
    {
      py::gil_scoped_release unlocked;
      const std::lock_guard lock(mutex_);
      const CompiledScene& scene = *scene_.compiled;
      for (py::ssize_t k = 0; k < n; ++k) {
        const Eigen::Vector3d p_W_hip(hip[3 * k], hip[3 * k + 1], hip[3 * k + 2]);
        const ProxyOutput out =
            step_proxy(scene.world, scene.materials, scene.proxy, state_, p_W_hip, dt[dt_per_row ? k : 0]);
        for (int i = 0; i < 3; ++i) {
          proxy[3 * k + i] = out.proxy_W[i];
          force[3 * k + i] = out.force_W[i];
        }
        contact[k] = out.in_contact;
        planes[k] = out.plane_count;
        object[k] = out.contact_object;
        exhausted[k] = out.budget_exhausted;
      }
    }
    return trace;
  }

  [[nodiscard]] py::array_t<double> proxy_W_m() {
    py::array_t<double> p(3);
    const std::lock_guard lock(mutex_);
    for (int i = 0; i < 3; ++i) p.mutable_data()[i] = state_.proxy_W[i];
    return p;
  }

  [[nodiscard]] const CompiledSceneHandle& scene() const noexcept { return scene_; }

 private:
  CompiledSceneHandle scene_;
  std::mutex mutex_;  ///< one step at a time: step() runs without the GIL
  ProxyState state_;
};

}  // namespace

void bind_proxy(py::module_& m) {
  py::class_<ProxyTrace>(m, "ProxyTrace", "What Proxy.step did, one row per HIP row.")
      .def_readonly("proxy_W_m", &ProxyTrace::proxy_W_m, "(N, 3) proxy in the world frame, m")
      .def_readonly("force_W_N", &ProxyTrace::force_W_N, "(N, 3) force on the hand, world frame, N")
      .def_readonly("contact", &ProxyTrace::contact, "(N,) bool")
      .def_readonly("planes", &ProxyTrace::planes, "(N,) int32 constraint planes at the end of each step")
      .def_readonly("contact_object", &ProxyTrace::contact_object, "(N,) int32 touched object, -1: none")
      .def_readonly("budget_exhausted", &ProxyTrace::budget_exhausted, "(N,) bool: the step hit its work budget")
      .def("__len__", [](const ProxyTrace& t) { return t.contact.shape(0); });

  py::class_<Proxy>(m, "Proxy",
                    "The scene's god-object proxy (docs/proxy.md): never crosses a surface, otherwise goes to "
                    "the hand. Proxy(scene, p_W_hip_m) starts it at a HIP in free space (ValueError otherwise).")
      .def(py::init<CompiledSceneHandle, const InputArray&>(), py::arg("scene"), py::arg("p_W_hip_m"))
      .def("reset", &Proxy::reset, py::arg("p_W_hip_m"),
           "Places the proxy at a HIP in free space, with no contact (ValueError otherwise).")
      .def("step", &Proxy::step, py::arg("p_W_hip_m"), py::arg("dt_s") = 1e-3,
           "Steps the proxy once per row of an (N, 3) array of HIP positions (world frame, m); dt_s is one "
           "time step for all rows or one per row (s, finite, > 0). A non-finite HIP leaves the proxy where "
           "it was with zero force. Returns a ProxyTrace; the proxy keeps its state for the next call.")
      .def_property_readonly("proxy_W_m", &Proxy::proxy_W_m, "Where the proxy is now (world frame, m)")
      .def_property_readonly("scene", &Proxy::scene);
}

}  // namespace mhd::python
