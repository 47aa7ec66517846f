# Renders a glTF model under a latitude-longitude environment with Blender's Cycles, as illum frames
# and displays it, for bench/compare_environment.sh:
#   blender -b --factory-startup -P render_model.py -- SCENE.json MODEL.gltf ENV.hdr OUT.png SAMPLES THREADS
# SCENE.json is what `illum render MODEL --save-scene` wrote: its camera, size, environment
# (colour, rotation) and display (tone map, encoding) are used, so the two pictures differ only by
# the renderer. The model goes through Blender's own glTF importer (Principled BSDF materials); the
# environment lights alone (no lamps), seen behind the model. Box-filtered pixels, no denoising.
import bpy, json, math, os, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from illum_cycles import add_camera, illum_root, setup_cycles

scene_path, model_path, env_path, out_path, samples, threads = sys.argv[sys.argv.index("--") + 1:][:6]
spec = json.load(open(scene_path))
scene = setup_cycles(spec, samples, threads)

# Debian 12's Blender 3.4 glTF importer still says numpy.bool, which Debian's numpy 1.24 no
# longer has (the alias was removed): give it back before importing.
import numpy
if not hasattr(numpy, "bool"):
    numpy.bool = bool
bpy.ops.import_scene.gltf(filepath=model_path)

# The environment. illum looks a direction d (its world, +Y up) up at u = 1/2 + atan2(d.x, −d.z)/2π;
# Blender (+Z up, d_B = (d.x, −d.z, d.y)) at u = 1/2 − atan2(d_B.y, d_B.x)/2π, a quarter turn
# apart: the lookup direction is turned −90° about Z, then by illum's rotation about its up axis.
world = bpy.data.worlds.new("environment")
world.use_nodes = True
nodes, links = world.node_tree.nodes, world.node_tree.links
background = nodes["Background"]
texture = nodes.new("ShaderNodeTexEnvironment")
texture.image = bpy.data.images.load(env_path)
texture.interpolation = "Linear"
coordinates = nodes.new("ShaderNodeTexCoord")
mapping = nodes.new("ShaderNodeMapping")
mapping.vector_type = "VECTOR"
mapping.inputs["Rotation"].default_value = (0, 0, math.radians(-90 - spec.get("environment_rotation", 0)))
links.new(coordinates.outputs["Generated"], mapping.inputs["Vector"])
links.new(mapping.outputs["Vector"], texture.inputs["Vector"])
links.new(texture.outputs["Color"], background.inputs["Color"])
strength = spec.get("environment", [1, 1, 1])
background.inputs["Strength"].default_value = sum(strength) / 3
scene.world = world

# illum's camera, in its +Y-up world (the importer turned the model into Blender's the same way).
add_camera(scene, illum_root(scene), spec["camera"])

exr = out_path + ".exr"
scene.render.filepath = exr
bpy.ops.render.render(write_still=True)

# illum's display, so that the pictures compare: the scene's tone map (docs/scene-format.md,
# "Display") and encoding, applied to Cycles' linear radiance; the bytes then written as they are.
def tone_mapped(x, kind):
    x = max(x, 0.0)
    if kind == "reinhard":
        return x / (1 + x)
    if kind == "aces":
        return x * (2.51 * x + 0.03) / (x * (2.43 * x + 0.59) + 0.14)
    return x

def encoded(x, kind):
    x = min(max(x, 0.0), 1.0)
    if kind == "srgb":
        return 12.92 * x if x <= 0.0031308 else 1.055 * x ** (1 / 2.4) - 0.055
    return x

tone, encoding = spec.get("tone_map", "none"), spec.get("encoding", "linear")
render = bpy.data.images.load(exr)
pixels = list(render.pixels)
for i in range(0, len(pixels), 4):
    for c in range(3):
        pixels[i + c] = encoded(tone_mapped(pixels[i + c], tone), encoding)
    pixels[i + 3] = 1.0
shown = bpy.data.images.new("shown", spec["width"], spec["height"], float_buffer=True)
shown.pixels = pixels
scene.view_settings.view_transform = "Standard"
scene.display_settings.display_device = "None"
scene.render.image_settings.file_format = "PNG"
scene.render.image_settings.color_depth = "8"
shown.save_render(out_path, scene=scene)
