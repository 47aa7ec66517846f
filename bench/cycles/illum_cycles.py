# What both Cycles scripts share (render_scene.py, render_model.py): Cycles set up as an unbiased
# reference for an illum scene (CPU, no denoising or adaptive sampling, no clamping, box-filtered
# pixels, the scene's bounce limit, linear 32-bit OpenEXR), and illum's camera in Blender's world.
import bpy, math
from mathutils import Matrix, Vector


def setup_cycles(spec, samples, threads):
    """An empty scene rendered by Cycles at the size and bounce limit of illum's scene `spec`."""
    bpy.ops.wm.read_factory_settings(use_empty=True)
    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = int(samples)
    scene.cycles.use_denoising = False
    scene.cycles.use_adaptive_sampling = False
    depth = spec.get("max_depth", 5)
    scene.cycles.max_bounces = depth
    for kind in ("diffuse", "glossy", "transmission", "volume", "transparent"):
        setattr(scene.cycles, kind + "_bounces", depth)
    scene.cycles.sample_clamp_direct = 0
    scene.cycles.sample_clamp_indirect = 0
    scene.cycles.filter_type = "BOX"
    scene.cycles.filter_width = 1.0
    scene.render.threads_mode = "FIXED"
    scene.render.threads = int(threads)
    scene.render.resolution_x = spec["width"]
    scene.render.resolution_y = spec["height"]
    scene.render.resolution_percentage = 100
    scene.render.film_transparent = False
    scene.view_settings.view_transform = "Standard"
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"
    return scene


def illum_root(scene):
    """An empty turned 90° about X: what hangs under it is in illum's +Y-up world (Blender's is +Z up)."""
    root = bpy.data.objects.new("illum", None)
    scene.collection.objects.link(root)
    root.rotation_euler = (math.pi / 2, 0, 0)
    return root


def add_camera(scene, root, cam):
    """illum's camera (its "camera" object: eye, center, up, fovy, near, far) as the scene's camera."""
    camera = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
    scene.collection.objects.link(camera)
    camera.parent = root
    eye, center = Vector(cam["eye"]), Vector(cam.get("center", [0, 0, 0]))
    up = Vector(cam.get("up", [0, 1, 0]))
    forward = (center - eye).normalized()
    right = forward.cross(up).normalized()
    true_up = right.cross(forward)
    camera.matrix_basis = Matrix((
        (right.x, true_up.x, -forward.x, eye.x),
        (right.y, true_up.y, -forward.y, eye.y),
        (right.z, true_up.z, -forward.z, eye.z),
        (0, 0, 0, 1)))
    camera.data.sensor_fit = "VERTICAL"
    camera.data.angle_y = math.radians(cam.get("fovy", 45))
    camera.data.clip_start = cam.get("near", 0.1)
    camera.data.clip_end = cam.get("far", 100)
    scene.camera = camera
    return camera
