/* MHD plugin ABI, version 6. The only header a plugin includes.
 *
 * A plugin is a shared library exporting one C function, mhd_plugin_entry, that returns
 * a table of function pointers (mhd_plugin_api). The host checks the table's ABI
 * version and struct size before calling anything else, then drives the lifecycle
 *   open(params) -> start -> [read/write ...] -> stop -> close.
 * read/write never block: they return MHD_NO_DATA when nothing new is there. The one
 * call allowed to block is the optional tracker_wait, which the host calls only from a
 * thread that may wait (never the haptic thread). The host makes one instance's calls one
 * at a time (the device's from the haptic thread, which must never wait on a lock), so a
 * plugin needs no mutex of its own around them.
 * Version 2 added the optional calls tracker_wait and counters at the end of the table.
 * Version 3 made devices Cartesian, as vendor SDKs are: a device reports its tool's pose
 * and velocity in its own frame D and receives a force (and, with 6 output DOF, a torque)
 * in D; joint kinematics live inside the device plugin. device_info replaced
 * device_limits, and every plugin declares its parameters (params, param_count), so the
 * host checks a scene's parameters without opening the plugin. A v2 plugin is refused.
 * Version 4 took the simulated world out of mhd_host: simulation is not the host's
 * business, so simulated backends share their world through a support library of their
 * own (libs/sim_world). A v3 plugin is refused.
 * Version 5 gave the base a lift: a vertical axis between the base and the arm, whose
 * height a base reports in mhd_base_state and whose speed the host commands in
 * mhd_base_command. A base without one leaves has_lift 0 and ignores lift_vmps. A v4
 * plugin is refused.
 * Version 6 added the link kind, which carries the states of objects several rigs share
 * and their users' pushes between the rigs (link_send, link_read at the end of the
 * table). A v5 plugin is refused.
 * All quantities are SI (metres, radians, seconds, newtons); device-native units
 * (millimetres, encoder counts) stay inside the plugin. Frames follow the engine's
 * X_AB naming: a pose of B given in A.
 *
 * The host validates everything a plugin returns (NaN, ranges, staleness) and clamps
 * every command it sends; a plugin never needs to trust the host's numbers either.
 *
 * Ending safely. The host ends every run with a zero device command and a zero base
 * command; when the process is dying (a plugin crashed, aborted, threw or called exit())
 * it sends both from a last-gasp path that may run in a signal handler, so device_write
 * and base_write should not wait on locks another thread may hold for long. What no
 * process survives (kill -9, power loss) the hardware must handle: a backend driving
 * real hardware MUST arm the hardware's own command timeout at start() (amplifier or
 * motor-controller watchdog: without a fresh command within that time, zero torque /
 * base stopped). The simulated backends model it (parameter command_timeout_s). */
#ifndef MHD_PLUGIN_ABI_H
#define MHD_PLUGIN_ABI_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define MHD_PLUGIN_ABI_VERSION 6u
#define MHD_PLUGIN_ENTRY_SYMBOL "mhd_plugin_entry"
#define MHD_ERROR_MESSAGE_SIZE 256

#if defined(_WIN32)
#define MHD_PLUGIN_EXPORT __declspec(dllexport)
#else
#define MHD_PLUGIN_EXPORT __attribute__((visibility("default")))
#endif

typedef enum mhd_plugin_kind {
  MHD_KIND_DEVICE = 1,  /* force-feedback arm */
  MHD_KIND_TRACKER = 2, /* pose tracker (head and base sensors) */
  MHD_KIND_BASE = 3,    /* mobile base */
  MHD_KIND_DISPLAY = 4, /* visual display */
  MHD_KIND_LINK = 5     /* link to the other rigs sharing objects with this one */
} mhd_plugin_kind;

typedef enum mhd_status {
  MHD_OK = 0,
  MHD_NO_DATA = 1,    /* read: nothing new since the last read (not an error) */
  MHD_ERROR = 2,      /* failed; the mhd_error says why */
  MHD_DEACTIVATE = 3  /* the hardware asks to be stopped (e.g. emergency stop pressed) */
} mhd_status;

/* Filled by the plugin whenever it returns MHD_ERROR or open() returns NULL. */
typedef struct mhd_error {
  char message[MHD_ERROR_MESSAGE_SIZE];
} mhd_error;

/* One parameter from the scene XML: <param name="..." value="..."/>. */
typedef struct mhd_param {
  const char* name;
  const char* value;
} mhd_param;

/* What kind of value a parameter takes (the text in the scene XML is parsed so). */
typedef enum mhd_param_type {
  MHD_PARAM_NUMBER = 1,     /* a finite decimal number, C locale */
  MHD_PARAM_INTEGER = 2,    /* a non-negative integer */
  MHD_PARAM_TEXT = 3,       /* a non-empty string */
  MHD_PARAM_VECTOR3 = 4,    /* three numbers separated by blanks, each in range */
  MHD_PARAM_QUATERNION = 5, /* four numbers "w x y z" of non-zero norm */
  MHD_PARAM_CHOICE = 6,     /* one of the words in choices */
  MHD_PARAM_BOOL = 7        /* "true" or "false" */
} mhd_param_type;

/* Range flags of a declaration. */
#define MHD_PARAM_HAS_MIN 1u       /* value >= min_value */
#define MHD_PARAM_HAS_MAX 2u       /* value <= max_value */
#define MHD_PARAM_MIN_EXCLUSIVE 4u /* with HAS_MIN: value > min_value */
#define MHD_PARAM_REQUIRED 8u      /* the scene must give it */
#define MHD_PARAM_MAX_EXCLUSIVE 16u /* with HAS_MAX: value < max_value */

/* One parameter a plugin accepts. The host checks a scene's <param>s against the
 * declarations before open() (unknown names, types, ranges, choices, required ones), so
 * `mhd validate` finds what open() would refuse; open() still checks its own rules that
 * involve several parameters. */
typedef struct mhd_param_decl {
  const char* name;          /* e.g. "rate_hz" */
  mhd_param_type type;
  const char* unit;          /* SI unit of numbers, e.g. "s", "m", "N/m"; "" when none */
  uint32_t flags;            /* MHD_PARAM_* range flags */
  double min_value;          /* numbers, integers, each component of a vector */
  double max_value;
  const char* choices;       /* MHD_PARAM_CHOICE: words separated by '|', e.g. "kinematic|impedance" */
  const char* default_value; /* what the plugin uses when absent, as text; NULL: none */
  const char* doc;           /* one line */
} mhd_param_decl;

/* One counter a plugin keeps, e.g. samples it dropped and why. */
typedef struct mhd_counter {
  const char* name; /* e.g. "dropped_stale"; a static string, valid while the library is loaded */
  uint64_t value;
} mhd_counter;

/* ---- data exchanged with each kind -------------------------------------------- */

/* Device: the tool's pose and velocity in the device's own frame D (the frame its
 * vendor SDK reports in; the scene places D in the world). timestamp_s is the host clock
 * (see mhd_host). A device with 3 input DOF reports q_D_tool_wxyz = (1, 0, 0, 0). */
typedef struct mhd_device_state {
  double timestamp_s;
  double p_D_tool_m[3];
  double v_D_tool_mps[3];
  double q_D_tool_wxyz[4]; /* unit quaternion w, x, y, z */
  uint32_t buttons;        /* bit i: button i pressed */
} mhd_device_state;

/* Device command: the force (and torque) to render at the tool, in D. The host clamps
 * both to the device's mhd_device_info first; the plugin maps them to its motors (for an
 * arm tau = J^T F) and must still respect its own motor limits. torque_D_Nm is all zero
 * for a device with 3 output DOF. */
typedef struct mhd_device_command {
  double timestamp_s;
  double force_D_N[3];
  double torque_D_Nm[3];
} mhd_device_command;

#define MHD_DEVICE_MAX_WORKSPACE_BOXES 4

/* An axis-aligned box in the device frame D. */
typedef struct mhd_box_D {
  double min_m[3];
  double max_m[3];
} mhd_box_D;

/* What a device is, reported after open(); the host clamps and checks with it. */
typedef struct mhd_device_info {
  double max_force_N;           /* > 0: the host never sends a larger force */
  double max_torque_Nm;         /* > 0 with 6 output DOF, 0 with 3 */
  double max_stiffness_N_per_m; /* > 0: the stiffest virtual spring the device renders stably */
  uint32_t dof_in;              /* 3 (position) or 6 (position and orientation) */
  uint32_t dof_out;             /* 3 (force) or 6 (force and torque) */
  uint32_t workspace_box_count; /* 1..MHD_DEVICE_MAX_WORKSPACE_BOXES */
  mhd_box_D workspace[MHD_DEVICE_MAX_WORKSPACE_BOXES]; /* their union is what the tool reaches */
} mhd_device_info;

/* Tracker: one pose sample of one sensor in the tracker's frame (X_T_sensor). */
typedef struct mhd_tracker_sample {
  uint32_t sensor_id;
  uint64_t sequence;     /* per sensor, increasing */
  double timestamp_s;    /* when the pose was measured, host clock */
  double p_T_m[3];       /* position */
  double q_T_wxyz[4];    /* orientation, unit quaternion w, x, y, z */
} mhd_tracker_sample;

/* Base: planar pose on the floor (world x, z; heading about world +y) and velocity; and
 * its lift, if it has one: the arm's height above where the rig file puts it (the lift at
 * 0) and its vertical speed, up positive. The host zeroes the struct before base_read, so
 * a base that fills none of the lift fields has none. */
typedef struct mhd_base_state {
  double timestamp_s;
  double x_m, z_m, heading_rad;
  double vx_mps, vz_mps, omega_radps; /* in the world frame */
  int32_t has_lift;                   /* 1: lift_m and lift_vmps are the lift's state */
  double lift_m, lift_vmps;
} mhd_base_state;

/* Base command: velocity in the base's own frame (x forward, y up, z to the right:
 * right-handed, as in the rig), and the lift's vertical speed (up positive; 0 holds it,
 * and every stop command is 0). A base limits the lift to its range and limits itself. */
typedef struct mhd_base_command {
  double timestamp_s;
  double vx_mps, vz_mps, omega_radps;
  double lift_vmps;
} mhd_base_command;

/* Display: a snapshot of the rig for drawing (world frame). */
typedef struct mhd_display_frame {
  double timestamp_s;
  double p_W_hip_m[3];
  double p_W_proxy_m[3];
  double force_W_N[3];
  int32_t in_contact;
  double base_x_m, base_z_m, base_heading_rad;
  double p_W_head_m[3];
  double q_W_head_wxyz[4];
} mhd_display_frame;

/* Link: what rigs sharing a pushable object tell each other (docs/shared-objects.md).
 * The object's authority sends its state every tick; every other rig sends the push its
 * user's hand gives the object. The host fills every field; a link carries the
 * messages as they are and hands on what the other rigs sent, never its own. timestamp_s
 * is the sender's host clock on send and must be the receiver's on read: a link between
 * machines carries it on a clock both share (e.g. synchronised wall-clock time). */
typedef enum mhd_link_message_kind {
  MHD_LINK_STATE = 1, /* the authority's state of the object */
  MHD_LINK_PUSH = 2   /* a rig's push on the object */
} mhd_link_message_kind;

typedef struct mhd_link_message {
  uint32_t kind;      /* mhd_link_message_kind */
  uint32_t object_id; /* the id the scenes' <shared_object id> give the object */
  uint32_t rig_id;    /* the sender */
  uint32_t term;      /* state: the authority's term (each hand-over starts a higher one) */
  uint64_t sequence;  /* per sender and kind, increasing */
  double timestamp_s;
  /* State: the object's pose in the world and its twist (velocity of its origin and
   * angular velocity, in W). */
  double p_W_m[3];
  double q_W_wxyz[4];
  double v_W_mps[3];
  double w_W_radps[3];
  /* Push: the force on the object (W), acting at p_O_m in the object's own frame. */
  double f_W_N[3];
  double p_O_m[3];
} mhd_link_message;

/* ---- what the host offers a plugin -------------------------------------------- */

typedef struct mhd_host {
  uint32_t abi_version;
  uint32_t struct_size;
  /* Monotonic host clock, seconds. */
  double (*now_s)(void* context);
  void* clock_context;
  /* Absolute path of the root scene XML the host runs, NULL when there is none. A display
   * plugin loads the scene's geometry from it; paths inside resolve against it. */
  const char* scene_file;
} mhd_host;

/* ---- the plugin's table ----------------------------------------------------- */

typedef struct mhd_plugin_instance mhd_plugin_instance; /* opaque, owned by the plugin */

typedef struct mhd_plugin_api {
  uint32_t abi_version; /* MHD_PLUGIN_ABI_VERSION the plugin was built against */
  uint32_t struct_size; /* sizeof(mhd_plugin_api) the plugin was built with */
  mhd_plugin_kind kind;
  const char* name;        /* unique, e.g. "sim_phantom" */
  const char* version;     /* the plugin's own version, e.g. "1.0.0" */
  const char* description; /* one line */

  /* Lifecycle. open() returns NULL and fills err on failure (unknown or bad parameter
   * included: a plugin rejects parameters it does not know). */
  mhd_plugin_instance* (*open)(const mhd_host* host, const mhd_param* params, size_t param_count, mhd_error* err);
  mhd_status (*start)(mhd_plugin_instance* self, mhd_error* err);
  mhd_status (*stop)(mhd_plugin_instance* self, mhd_error* err);
  void (*close)(mhd_plugin_instance* self);

  /* The parameters open() accepts (param_count entries; NULL with 0 for none). */
  const mhd_param_decl* params;
  size_t param_count;

  /* Kind-specific calls; NULL for the kinds a plugin is not. Never block. */
  mhd_status (*device_info)(mhd_plugin_instance* self, mhd_device_info* out, mhd_error* err);
  mhd_status (*device_read)(mhd_plugin_instance* self, mhd_device_state* out, mhd_error* err);
  mhd_status (*device_write)(mhd_plugin_instance* self, const mhd_device_command* command, mhd_error* err);
  /* Copies up to capacity samples received since the last call; *count says how many. */
  mhd_status (*tracker_read)(mhd_plugin_instance* self, mhd_tracker_sample* out, size_t capacity, size_t* count,
                             mhd_error* err);
  mhd_status (*base_read)(mhd_plugin_instance* self, mhd_base_state* out, mhd_error* err);
  mhd_status (*base_write)(mhd_plugin_instance* self, const mhd_base_command* command, mhd_error* err);
  mhd_status (*display_write)(mhd_plugin_instance* self, const mhd_display_frame* frame, mhd_error* err);
  /* Simulated backends only (may be NULL): advance the simulation to host time t_s. */
  mhd_status (*simulate_until)(mhd_plugin_instance* self, double t_s, mhd_error* err);

  /* Optional (may be NULL), trackers only: blocks until tracker_read has data or
   * timeout_s passes; MHD_OK when there is data, MHD_NO_DATA on timeout. Lets the host
   * take a sample the moment it arrives instead of at its next poll. */
  mhd_status (*tracker_wait)(mhd_plugin_instance* self, double timeout_s, mhd_error* err);
  /* Optional (may be NULL), any kind: writes up to capacity counters into out and the
   * number the plugin keeps into *count (names and order fixed while it is open). The
   * host calls it from the thread that makes the plugin's other calls, a few times a
   * second, and shows the counts in its status. */
  mhd_status (*counters)(mhd_plugin_instance* self, mhd_counter* out, size_t capacity, size_t* count,
                         mhd_error* err);

  /* Link only (version 6). link_send hands count messages to the other rigs; it never
   * waits (a link that cannot keep up drops, and counts). link_read copies up to capacity
   * messages received since the last call; *count says how many. */
  mhd_status (*link_send)(mhd_plugin_instance* self, const mhd_link_message* messages, size_t count, mhd_error* err);
  mhd_status (*link_read)(mhd_plugin_instance* self, mhd_link_message* out, size_t capacity, size_t* count,
                          mhd_error* err);
} mhd_plugin_api;

/* The one exported entry point. host_abi_version lets a plugin refuse a host it cannot
 * serve (return NULL); otherwise it returns its static table. */
typedef const mhd_plugin_api* (*mhd_plugin_entry_fn)(uint32_t host_abi_version);
MHD_PLUGIN_EXPORT const mhd_plugin_api* mhd_plugin_entry(uint32_t host_abi_version);

#ifdef __cplusplus
}
#endif

#endif /* MHD_PLUGIN_ABI_H */
