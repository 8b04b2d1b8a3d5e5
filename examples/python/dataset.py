"""N views of a model from a sphere of camera poses: RGB PNGs, depth (float32 .npy, metres along
the camera axis), object masks (PNG) and cameras.json with the intrinsics and the camera-to-world
poses (OpenCV axes). Usage: dataset.py MODEL OUT_DIR [VIEWS [UP]] (UP: y or z, the model's up axis)"""
import json, pathlib, sys
import numpy as np
import phongvk

model, out, views, up = sys.argv[1], pathlib.Path(sys.argv[2]), int((sys.argv + ["12"])[3]), (sys.argv + [None] * 4)[4]
width, height, f = 640, 480, 500.0
scene = phongvk.load_scene(model, up=up)  # the model alone, lit from the camera
low, high = np.array(scene.bounds)
centre, radius = (low + high) / 2, np.linalg.norm(high - low) / 2
renderer, cameras = phongvk.Renderer("gpu"), []
out.mkdir(parents=True, exist_ok=True)
for i in range(views):  # a Fibonacci spiral over the sphere, poles left out
    z, angle = 0.9 * (1 - 2 * (i + 0.5) / views), i * np.pi * (3 - np.sqrt(5))
    eye = centre + 2.5 * radius * np.array([np.sqrt(1 - z * z) * np.cos(angle), np.sqrt(1 - z * z) * np.sin(angle), z])
    forward = (centre - eye) / np.linalg.norm(centre - eye)
    right = np.cross(forward, (0, 0, 1)) / np.linalg.norm(np.cross(forward, (0, 0, 1)))
    pose = np.eye(4)
    pose[:3, :3], pose[:3, 3] = np.stack([right, np.cross(forward, right), forward], axis=1), eye
    scene.camera = phongvk.Camera.from_intrinsics(f, f, (width - 1) / 2, (height - 1) / 2, width, height, pose=pose,
                                                  convention="opencv")
    frame = renderer.render(scene, outputs=["color", "depth", "object_id"])
    phongvk.write_png(out / f"{i:03d}_rgb.png", frame["color"])
    np.save(out / f"{i:03d}_depth.npy", frame["depth"])
    phongvk.write_png(out / f"{i:03d}_mask.png", frame["object_id"] >= 0)  # 8-bit grey, 0 and 255
    cameras.append({"file": f"{i:03d}_rgb.png", "camera_to_world": pose.tolist()})
intrinsics = {"fx": f, "fy": f, "cx": (width - 1) / 2, "cy": (height - 1) / 2, "width": width, "height": height}
(out / "cameras.json").write_text(json.dumps({"intrinsics": intrinsics, "convention": "opencv", "views": cameras}, indent=1))
print(f"{views} views of {model} in {out}")
