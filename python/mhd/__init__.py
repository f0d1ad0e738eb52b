"""MHD's haptic rendering engine from Python (docs/python.md).

Scenes: read_scene, read_scene_string, validate, compile_scene, load_scene.
The god-object proxy over NumPy arrays: Proxy, replay_proxy.
The planner simulator (thesis ch. 3.6): plan_sim_cases, plan_sim_map.
Recordings as NumPy structured arrays: read_recording.
The haptic server on (simulated) plugins: run_server.
Problems in user input raise MhdError with the engine's file:line message; bad arguments
raise ValueError. Long calls (compiling, stepping, simulating, a server run) release the GIL.
"""

import numpy as np

from ._mhd import (  # noqa: F401  (the package's API)
    CompiledScene,
    Diagnostic,
    MhdError,
    Proxy,
    ProxyTrace,
    Scene,
    ServerReport,
    ServerStatus,
    compile_scene,
    plan_sim_cases,
    plan_sim_map,
    read_recording,
    read_scene,
    read_scene_string,
    recording_columns,
    recording_dtype,
    run_server,
    validate,
)

__all__ = [
    "CompiledScene", "Diagnostic", "MhdError", "Proxy", "ProxyTrace", "Scene", "ServerReport", "ServerStatus",
    "compile_scene", "load_scene", "plan_sim_cases", "plan_sim_map", "read_recording", "read_scene",
    "read_scene_string", "recording_columns", "recording_dtype", "replay_proxy", "run_server", "validate",
]

# dt of the only step of a one-row path, as `mhd proxy-replay` takes it.
_SINGLE_ROW_DT_S = 1e-3


def load_scene(file, use_cache=True):
    """read_scene then compile_scene: a CompiledScene ready to touch or run."""
    return compile_scene(read_scene(file), use_cache=use_cache)


def replay_proxy(scene, t_s, p_W_hip_m):
    """Replays a HIP path through a compiled scene's proxy, as `mhd proxy-replay` does
    (docs/proxy_replay.md): the proxy starts at the first HIP (which must be in free space),
    then steps once per row with dt = t[k] - t[k-1]; the first row takes the second row's dt
    (1 ms for a one-row path). t_s: (N,) increasing times in s; p_W_hip_m: (N, 3) HIP in the
    world frame in m. Returns a ProxyTrace (proxy, force, contact arrays, one row per tick)."""
    t = np.ascontiguousarray(t_s, dtype=np.float64)
    hip = np.ascontiguousarray(p_W_hip_m, dtype=np.float64)
    if t.ndim != 1 or hip.shape != (t.shape[0], 3) or t.shape[0] == 0:
        raise ValueError(f"t_s must have shape (N,) and p_W_hip_m (N, 3) with N >= 1; got {t.shape} and {hip.shape}")
    if not np.all(np.isfinite(t)):
        raise ValueError(f"t_s[{int(np.argmin(np.isfinite(t)))}] is not finite")
    dt = np.diff(t)
    if np.any(dt <= 0):
        k = int(np.argmax(dt <= 0)) + 1
        raise ValueError(f"t_s must increase: t_s[{k}] = {t[k]!r} after {t[k - 1]!r}")
    dt = np.concatenate(([dt[0] if dt.size else _SINGLE_ROW_DT_S], dt))
    return Proxy(scene, hip[0]).step(hip, dt)
