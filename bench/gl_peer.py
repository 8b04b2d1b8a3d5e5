"""What the peer benchmarks (peers.py, peers_points.py) share about moderngl: whether it can run
here, and the OpenGL view and projection matrices they give it; numpy only, so a moderngl process
imports nothing of phongvk for them."""

import numpy as np


def look_at(eye, centre, up):
    f = centre - eye
    f /= np.linalg.norm(f)
    s = np.cross(f, up)
    s /= np.linalg.norm(s)
    u = np.cross(s, f)
    m = np.eye(4)
    m[0, :3], m[1, :3], m[2, :3] = s, u, -f
    m[:3, 3] = -m[:3, :3] @ eye
    return m


def perspective(fov, aspect, near, far):
    t = 1 / np.tan(np.radians(fov) / 2)
    m = np.zeros((4, 4))
    m[0, 0], m[1, 1] = t / aspect, t
    m[2, 2], m[2, 3] = (far + near) / (near - far), 2 * far * near / (near - far)
    m[3, 2] = -1
    return m


def unavailable(name):
    """Why a renderer cannot run here, or None."""
    if name != "moderngl":
        return None
    try:
        import moderngl
        moderngl.create_standalone_context(backend="egl").release()
    except Exception as e:  # not installed, or no EGL device
        return f"not available: {type(e).__name__}: {str(e).splitlines()[0] if str(e) else ''}".strip()
    return None
