/* c_frame_counter: an MHD display plugin in plain C11, built out of tree (CMakeLists.txt
 * here, or with pkg-config: docs/plugins.md). It counts the frames the host gives it,
 * reports the count as a counter while running and prints it to stderr on stop:
 *   c_frame_counter: <N> frames
 * It takes no parameters. Includes only <mhd/plugin_abi.h>. */
#include <mhd/plugin_abi.h>

#include <stdio.h>
#include <stdlib.h>

/* The file must be libmhd_<NAME>.so: mhd_add_plugin(NAME c_frame_counter ...). */
#define PLUGIN_NAME "c_frame_counter"

typedef struct frame_counter {
  uint64_t frames;
} frame_counter;

static frame_counter* self_of(mhd_plugin_instance* self) { return (frame_counter*)(void*)self; }

static mhd_plugin_instance* counter_open(const mhd_host* host, const mhd_param* params, size_t param_count,
                                         mhd_error* err) {
  (void)host;
  if (param_count > 0) {
    snprintf(err->message, sizeof(err->message), "unknown parameter '%s' (" PLUGIN_NAME " takes none)",
             params[0].name);
    return NULL;
  }
  frame_counter* counter = calloc(1, sizeof(frame_counter));
  if (counter == NULL) {
    snprintf(err->message, sizeof(err->message), "out of memory");
    return NULL;
  }
  return (mhd_plugin_instance*)(void*)counter;
}

static mhd_status counter_start(mhd_plugin_instance* self, mhd_error* err) {
  (void)self;
  (void)err;
  return MHD_OK;
}

static mhd_status counter_stop(mhd_plugin_instance* self, mhd_error* err) {
  (void)err;
  fprintf(stderr, PLUGIN_NAME ": %llu frames\n", (unsigned long long)self_of(self)->frames);
  return MHD_OK;
}

static void counter_close(mhd_plugin_instance* self) { free(self_of(self)); }

static mhd_status counter_write(mhd_plugin_instance* self, const mhd_display_frame* frame, mhd_error* err) {
  (void)frame;
  (void)err;
  ++self_of(self)->frames;
  return MHD_OK;
}

static mhd_status counter_counters(mhd_plugin_instance* self, mhd_counter* out, size_t capacity, size_t* count,
                                   mhd_error* err) {
  (void)err;
  *count = 1;
  if (capacity >= 1) {
    out[0].name = "frames";
    out[0].value = self_of(self)->frames;
  }
  return MHD_OK;
}

MHD_PLUGIN_EXPORT const mhd_plugin_api* mhd_plugin_entry(uint32_t host_abi_version) {
  /* Designated initialisers: every call left out is NULL. */
  static const mhd_plugin_api api = {
      .abi_version = MHD_PLUGIN_ABI_VERSION,
      .struct_size = sizeof(mhd_plugin_api),
      .kind = MHD_KIND_DISPLAY,
      .name = PLUGIN_NAME,
      .version = "1.0.0",
      .description = "Counts display frames (C example, built out of tree)",
      .open = counter_open,
      .start = counter_start,
      .stop = counter_stop,
      .close = counter_close,
      .display_write = counter_write,
      .counters = counter_counters,
  };
  if (host_abi_version != MHD_PLUGIN_ABI_VERSION) return NULL; /* a host we were not built for */
  return &api;
}
