/* A stand-in for a Cartesian haptic vendor's C SDK, for the example plugin beside it
 * (docs/plugins.md). No vendor SDK ships in Debian, so this one simulates its device: the
 * user's hand holds the handle like a spring (2 mm per newton about a rest point), and
 * the API speaks as vendors' do: millimetres, integer error codes, a device handle.
 * Devices: any serial starting with "SIM-" (rest point 10, 20, 30 mm). */
#ifndef VENDOR_SDK_H
#define VENDOR_SDK_H

#ifdef __cplusplus
extern "C" {
#endif

#define VC_OK 0
#define VC_ERR_NO_DEVICE 1     /* no device with that serial number */
#define VC_ERR_BAD_ARGUMENT 2  /* a NULL pointer or an out-of-range value */
#define VC_ERR_FORCE_LIMIT 3   /* a force above vc_max_force_N */

typedef struct vc_device vc_device;

int vc_open(const char* serial, vc_device** out);
void vc_close(vc_device* device);
const char* vc_error_string(int code);

/* The device zeroes its force when no vc_set_force_N arrives for this long. */
int vc_set_watchdog_ms(vc_device* device, unsigned ms);
/* Motor power: forces are rendered only while enabled. */
int vc_enable_forces(vc_device* device, int on);

double vc_max_force_N(const vc_device* device);
double vc_max_stiffness_N_per_mm(const vc_device* device);
int vc_get_workspace_mm(const vc_device* device, double min_mm[3], double max_mm[3]);

/* The handle in the device's frame, millimetres and millimetres per second. */
int vc_get_position_mm(vc_device* device, double p_mm[3]);
int vc_get_velocity_mm_s(vc_device* device, double v_mm_s[3]);
unsigned vc_get_buttons(const vc_device* device);
int vc_set_force_N(vc_device* device, const double force_N[3]);

#ifdef __cplusplus
}
#endif

#endif /* VENDOR_SDK_H */
