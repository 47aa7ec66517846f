# Renders an illum path-tracing scene file with Blender's Cycles, as an independent path tracer:
#   blender -b --factory-startup -P render_scene.py -- SCENE.json OUT.exr SAMPLES THREADS
# Reads the subset the Cornell box uses: inline triangle meshes and GLUT cubes with their transform
# lists, GL materials' diffuse colour as a Lambertian albedo, emission × emission_strength from
# front faces only (as illum's area lights), no point lights, a black environment. Box-filtered
# pixels, no denoising, the scene's bounce limit; written as linear 32-bit OpenEXR.
import bpy, json, math, os, sys
from mathutils import Matrix, Vector

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from illum_cycles import add_camera, illum_root, setup_cycles

scene_path, out_path, samples, threads = sys.argv[sys.argv.index("--") + 1:][:4]
spec = json.load(open(scene_path))
scene = setup_cycles(spec, samples, threads)
world = bpy.data.worlds.new("black")
world.use_nodes = True
world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
scene.world = world

# illum's world is +Y up; Blender's +Z: everything hangs under an empty turned 90° about X.
root = illum_root(scene)

def transform(steps):
    m = Matrix.Identity(4)
    for step in steps:
        if "translate" in step:
            m = m @ Matrix.Translation(Vector(step["translate"]))
        elif "rotate" in step:
            a = step["rotate"]
            m = m @ Matrix.Rotation(math.radians(a[0]), 4, Vector(a[1:4]).normalized())
        elif "scale" in step:
            s = step["scale"]
            m = m @ Matrix.Diagonal(Vector((s[0], s[1], s[2], 1.0)))
    return m

def material(spec_material, name):
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    nodes.clear()
    out = nodes.new("ShaderNodeOutputMaterial")
    diffuse = nodes.new("ShaderNodeBsdfDiffuse")
    d = spec_material.get("diffuse", [0.8, 0.8, 0.8])
    diffuse.inputs["Color"].default_value = (d[0], d[1], d[2], 1)
    diffuse.inputs["Roughness"].default_value = 0.0
    shader = diffuse.outputs["BSDF"]
    e = spec_material.get("emission", [0, 0, 0])
    if any(e):
        strength = spec_material.get("emission_strength", 1.0)
        emission = nodes.new("ShaderNodeEmission")
        emission.inputs["Color"].default_value = (e[0], e[1], e[2], 1)
        # Front faces only: strength × (1 − backfacing).
        geometry = nodes.new("ShaderNodeNewGeometry")
        front = nodes.new("ShaderNodeMath")
        front.operation = "SUBTRACT"
        front.inputs[0].default_value = 1.0
        links.new(geometry.outputs["Backfacing"], front.inputs[1])
        scaled = nodes.new("ShaderNodeMath")
        scaled.operation = "MULTIPLY"
        scaled.inputs[1].default_value = strength
        links.new(front.outputs[0], scaled.inputs[0])
        links.new(scaled.outputs[0], emission.inputs["Strength"])
        add = nodes.new("ShaderNodeAddShader")
        links.new(diffuse.outputs["BSDF"], add.inputs[0])
        links.new(emission.outputs["Emission"], add.inputs[1])
        shader = add.outputs["Shader"]
    links.new(shader, out.inputs["Surface"])
    return mat

for i, o in enumerate(spec["objects"]):
    mesh_spec = o["mesh"]
    mesh = bpy.data.meshes.new("mesh%d" % i)
    if mesh_spec["type"] == "triangles":
        p, idx = mesh_spec["positions"], mesh_spec["indices"]
        verts = [tuple(p[3 * k:3 * k + 3]) for k in range(len(p) // 3)]
        faces = [tuple(idx[3 * k:3 * k + 3]) for k in range(len(idx) // 3)]
    elif mesh_spec["type"] == "cube":
        h = mesh_spec.get("size", 1.0) / 2
        verts = [(x, y, z) for x in (-h, h) for y in (-h, h) for z in (-h, h)]
        faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    else:
        raise SystemExit("render_scene.py: mesh type %s is not supported" % mesh_spec["type"])
    mesh.from_pydata(verts, [], faces)
    mesh.update()
    obj = bpy.data.objects.new("object%d" % i, mesh)
    scene.collection.objects.link(obj)
    obj.parent = root
    obj.matrix_parent_inverse = Matrix.Identity(4)
    obj.matrix_basis = transform(o.get("transform", []))
    obj.data.materials.append(material(o.get("material", {}), "material%d" % i))

add_camera(scene, root, spec["camera"])

scene.render.filepath = out_path
bpy.ops.render.render(write_still=True)
