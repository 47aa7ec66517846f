# Renders an illum path-tracing scene file with Blender's Cycles, as an independent path tracer:
#   blender -b --factory-startup -P render_scene.py -- SCENE.json OUT.exr SAMPLES THREADS [MESHES.json]
# Reads inline triangle meshes and GLUT cubes with their transform lists or, with MESHES.json
# (bench/scene_meshes.cpp: every object's triangles in world space, as illum tessellates them),
# any scene's shapes. GL materials: the diffuse colour as a Lambertian albedo, the specular colour
# as a Beckmann lobe of the roughness whose distribution matches (N·H)^shininess (Walter et al.
# 2007: α = √(2/(n+2))), `reflective` k as an ideal mirror of colour k over (1 − k) of the rest,
# as illum's path tracer weighs them; emission × emission_strength from front faces only (as
# illum's area lights). GL lights as illum's path tracer lights with them: a point light of
# irradiance π·colour·attenuation·spot·cos (GL's 1/(a + bd + cd²) and (cos)^exponent inside the
# cutoff, as the lights' node trees), a sun for a directional one; a light's diffuse colour
# lights the diffuse lobe alone and its specular colour the glossy lobes alone. The scene's
# "environment" colour lights what rays escape to (the camera sees the background colour);
# without one, a black environment. Box-filtered pixels, no denoising, the scene's bounce limit;
# written as linear 32-bit OpenEXR.
import bpy, json, math, os, sys
from mathutils import Matrix, Vector

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from illum_cycles import add_camera, illum_root, setup_cycles

args = sys.argv[sys.argv.index("--") + 1:]
scene_path, out_path, samples, threads = args[:4]
spec = json.load(open(scene_path))
meshes = json.load(open(args[4]))["objects"] if len(args) > 4 else None
scene = setup_cycles(spec, samples, threads)
world = bpy.data.worlds.new("world")
world.use_nodes = True
environment = spec.get("environment")
if environment is None or isinstance(environment, str):
    world.node_tree.nodes["Background"].inputs["Strength"].default_value = 0.0
else:
    # Escaping rays see the environment; camera rays the background colour.
    nodes, links = world.node_tree.nodes, world.node_tree.links
    seen = nodes["Background"]
    seen.inputs["Color"].default_value = tuple(environment[:3]) + (1,)
    shown = nodes.new("ShaderNodeBackground")
    shown.inputs["Color"].default_value = tuple(spec.get("background", [0, 0, 0])[:3]) + (1,)
    path = nodes.new("ShaderNodeLightPath")
    mix = nodes.new("ShaderNodeMixShader")
    links.new(path.outputs["Is Camera Ray"], mix.inputs["Fac"])
    links.new(seen.outputs["Background"], mix.inputs[1])
    links.new(shown.outputs["Background"], mix.inputs[2])
    links.new(mix.outputs["Shader"], nodes["World Output"].inputs["Surface"])
scene.world = world
model = spec.get("model", "blinn-phong")

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
    k = (spec_material.get("reflective", [0, 0, 0]) + [0, 0, 0])[:3]
    rest = [1 - c for c in k]

    def add(a, b):
        node = nodes.new("ShaderNodeAddShader")
        links.new(a, node.inputs[0])
        links.new(b, node.inputs[1])
        return node.outputs["Shader"]

    def glossy(colour, roughness):
        node = nodes.new("ShaderNodeBsdfGlossy")
        node.distribution = "BECKMANN" if roughness > 0 else "SHARP"
        node.inputs["Color"].default_value = tuple(colour) + (1,)
        node.inputs["Roughness"].default_value = roughness  # Cycles' roughness is √α
        return node.outputs["BSDF"]

    diffuse = nodes.new("ShaderNodeBsdfDiffuse")
    d = spec_material.get("diffuse", [0.8, 0.8, 0.8])
    diffuse.inputs["Color"].default_value = (d[0] * rest[0], d[1] * rest[1], d[2] * rest[2], 1)
    diffuse.inputs["Roughness"].default_value = 0.0
    shader = diffuse.outputs["BSDF"]
    specular = spec_material.get("specular", [0, 0, 0])
    shininess = spec_material.get("shininess", 0)
    if model in ("blinn-phong", "phong") and any(specular[:3]):
        alpha = math.sqrt(2 / (shininess + 2))
        lobe = glossy([specular[c] * rest[c] for c in range(3)], math.sqrt(alpha))
        # illum's lobe ks·(n+8)/(8π)·(N·H)^n is about ks·D/4; Cycles' microfacet one is
        # ks·D·G/(4 cos_i cos_o). Its colour times cos_o², which is cos_i·cos_o at the lobe's peak
        # (the mirror direction), makes it about illum's where a shiny lobe's light comes from.
        geometry = nodes.new("ShaderNodeNewGeometry")
        cos = nodes.new("ShaderNodeVectorMath")
        cos.operation = "DOT_PRODUCT"
        links.new(geometry.outputs["Normal"], cos.inputs[0])
        links.new(geometry.outputs["Incoming"], cos.inputs[1])
        squared = nodes.new("ShaderNodeMath")
        squared.operation = "MULTIPLY"
        links.new(cos.outputs["Value"], squared.inputs[0])
        links.new(cos.outputs["Value"], squared.inputs[1])
        tint = nodes.new("ShaderNodeVectorMath")
        tint.operation = "SCALE"
        tint.inputs[0].default_value = tuple(specular[c] * rest[c] for c in range(3))
        links.new(squared.outputs[0], tint.inputs["Scale"])
        links.new(tint.outputs["Vector"], lobe.node.inputs["Color"])
        shader = add(shader, lobe)
    if any(k):
        shader = add(shader, glossy(k, 0.0))
    e = spec_material.get("emission", [0, 0, 0])
    if any(e[:3]):
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
        links.new(shader, add.inputs[0])
        links.new(emission.outputs["Emission"], add.inputs[1])
        shader = add.outputs["Shader"]
    links.new(shader, out.inputs["Surface"])
    return mat

for i, o in enumerate(spec["objects"]):
    mesh_spec = o["mesh"]
    mesh = bpy.data.meshes.new("mesh%d" % i)
    normals = None
    if meshes is not None:  # illum's own triangles, in world space
        p, idx = meshes[i]["positions"], meshes[i]["indices"]
        verts = [tuple(p[3 * k:3 * k + 3]) for k in range(len(p) // 3)]
        faces = [tuple(idx[3 * k:3 * k + 3]) for k in range(len(idx) // 3)]
        n = meshes[i]["normals"]
        normals = [tuple(n[3 * k:3 * k + 3]) for k in range(len(n) // 3)] or None
        o = dict(o, transform=[])
    elif mesh_spec["type"] == "triangles":
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
    if normals:  # illum's vertex normals, interpolated as its shading normals are
        mesh.polygons.foreach_set("use_smooth", [True] * len(mesh.polygons))
        mesh.use_auto_smooth = True
        mesh.normals_split_custom_set_from_vertices(normals)
    mesh.update()
    obj = bpy.data.objects.new("object%d" % i, mesh)
    scene.collection.objects.link(obj)
    obj.parent = root
    obj.matrix_parent_inverse = Matrix.Identity(4)
    obj.matrix_basis = transform(o.get("transform", []))
    obj.data.materials.append(material(o.get("material", {}), "material%d" % i))

# A point light's node strength S gives a white Lambertian surface facing it at any distance the
# radiance S/(4π²) through the Light Falloff node's Constant output (Cycles 3.4, measured: 0.0253302
# for S = 1 at 2 m and 3 m, box-filtered, 64 samples; without the node a 1 W light gives 1/(4π²d²)).
# illum's path tracer gives kd·att·colour·spot there (irradiance π·att·spot·cos, BRDF kd/π).
POINT_STRENGTH = 4 * math.pi ** 2


def illum_to_blender(v):
    """A direction of illum's +Y-up world in Blender's +Z-up one (the root's turn about X)."""
    return Vector((v[0], -v[2], v[1]))


def point_light(name, colour, position, l):
    light = bpy.data.lights.new(name, "POINT")
    light.shadow_soft_size = 0.0
    light.energy = 1.0
    light.use_nodes = True
    nodes, links = light.node_tree.nodes, light.node_tree.links
    emission = nodes["Emission"]
    emission.inputs["Color"].default_value = tuple(colour) + (1,)

    def math_node(operation, a, b):
        node = nodes.new("ShaderNodeMath")
        node.operation = operation
        for socket, value in zip(node.inputs, (a, b)):
            if isinstance(value, (int, float)):
                socket.default_value = value
            else:
                links.new(value, socket)
        return node.outputs[0]

    # GL's attenuation 1/(a + b·d + c·d²) of the distance d along the light's ray.
    a, b, c = (l.get("attenuation", [1, 0, 0]) + [0, 0, 0])[:3]
    d = nodes.new("ShaderNodeLightPath").outputs["Ray Length"]
    denominator = math_node("ADD", math_node("ADD", a, math_node("MULTIPLY", b, d)),
                            math_node("MULTIPLY", c, math_node("MULTIPLY", d, d)))
    strength = math_node("DIVIDE", POINT_STRENGTH, denominator)
    cutoff = l.get("spot_cutoff", 180)
    if cutoff < 180:
        # GL's spot: (cos γ)^exponent inside the cutoff, γ between the spot direction and the ray
        # from the light (a point light's shading normal in Cycles).
        axis = illum_to_blender(l.get("spot_direction", [0, 0, -1])).normalized()
        dot = nodes.new("ShaderNodeVectorMath")
        dot.operation = "DOT_PRODUCT"
        links.new(nodes.new("ShaderNodeNewGeometry").outputs["Normal"], dot.inputs[0])
        dot.inputs[1].default_value = axis
        cos = math_node("MAXIMUM", dot.outputs["Value"], 0.0)
        inside = math_node("GREATER_THAN", cos, math.cos(math.radians(cutoff)) - 1e-7)
        spot = math_node("MULTIPLY", inside, math_node("POWER", cos, l.get("spot_exponent", 0)))
        strength = math_node("MULTIPLY", strength, spot)
    falloff = nodes.new("ShaderNodeLightFalloff")
    links.new(strength, falloff.inputs["Strength"])
    links.new(falloff.outputs["Constant"], emission.inputs["Strength"])
    obj = bpy.data.objects.new(name, light)
    obj.location = Vector(position[:3])
    return obj


def sun_light(name, colour, towards):
    light = bpy.data.lights.new(name, "SUN")
    light.angle = 0.0
    light.energy = math.pi  # irradiance π·colour·cos, as illum's directional lights
    light.color = tuple(colour)
    obj = bpy.data.objects.new(name, light)
    # A sun shines down its −Z: turned to shine away from `towards` (the light's direction).
    obj.rotation_euler = Vector((0, 0, 1)).rotation_difference(Vector(towards).normalized()).to_euler()
    return obj


for i, l in enumerate(spec.get("lights", [])):
    position = l.get("position", [0, 0, 1, 0])
    for lobe in ("diffuse", "specular"):
        colour = (l.get(lobe, [0, 0, 0]) + [0, 0, 0])[:3]
        if not any(colour):
            continue
        name = "light%d_%s" % (i, lobe)
        if position[3] == 0:
            obj = sun_light(name, colour, position[:3])
        else:
            obj = point_light(name, colour, [p / position[3] for p in position[:3]], l)
        scene.collection.objects.link(obj)
        obj.parent = root
        obj.matrix_parent_inverse = Matrix.Identity(4)
        obj.visible_diffuse = lobe == "diffuse"
        obj.visible_glossy = lobe == "specular"

add_camera(scene, root, spec["camera"])

scene.render.filepath = out_path
bpy.ops.render.render(write_still=True)
