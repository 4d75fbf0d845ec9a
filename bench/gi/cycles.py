# Renders a scene of bench/gi/scenes.py with Blender's Cycles, set to compute what crtc's
# path tracer computes (see bench/README.md, "Global illumination"):
#
#   blender -b --factory-startup --python bench/gi/cycles.py -- \
#       --scene NAME --size WxH --samples N --bounces B --threads T --out FILE.exr [--dir DIR]
#       [--adaptive THRESHOLD]
#
# --adaptive turns on Cycles' adaptive sampling with that noise threshold (its default is
# 0.01), --samples then being the most a pixel takes; without it every pixel takes --samples.
# --bounces is crtc's count (surfaces a path may bounce off); Cycles counts the bounces
# after the first surface, so it is given B - 1. --dir is where sky.exr is.
import math
import os
import sys
import time

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import scenes  # noqa: E402

# How far the panorama is turned about Blender's z axis (up) so that Cycles sees it as crtc
# does: Cycles reads the image's centre column towards +x, crtc towards +z (Blender's +y),
# and both turn the same way with u. Checked by rendering the sky alone (bench/README.md).
SKY_ROTATE_Z = -math.pi / 2


def options(argv):
    argv = argv[argv.index("--") + 1:] if "--" in argv else []
    o = {"scene": "cornell", "size": "128x128", "samples": "16", "bounces": "8", "threads": "2",
         "out": "out.exr", "dir": ".", "seed": "0", "adaptive": "0"}
    i = 0
    while i < len(argv):
        name = argv[i].lstrip("-")
        if name not in o or i + 1 >= len(argv):
            raise SystemExit("cycles.py: bad option %r" % argv[i])
        o[name] = argv[i + 1]
        i += 2
    return o


def blender(p):
    """crtc/POV-Ray coordinates (left-handed, y up) to Blender's (right-handed, z up)."""
    return (p[0], p[2], p[1])


def material(name, m):
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    nodes.clear()
    out = nodes.new("ShaderNodeOutputMaterial")
    if m["kind"] == "diffuse":
        bsdf = nodes.new("ShaderNodeBsdfDiffuse")
        bsdf.inputs["Color"].default_value = (*m["color"], 1.0)
        bsdf.inputs["Roughness"].default_value = 0.0  # Lambert
        links.new(bsdf.outputs[0], out.inputs["Surface"])
    elif m["kind"] == "emitter":
        e = nodes.new("ShaderNodeEmission")
        e.inputs["Color"].default_value = (*m["color"], 1.0)
        e.inputs["Strength"].default_value = 1.0
        links.new(e.outputs[0], out.inputs["Surface"])
    else:
        g = nodes.new("ShaderNodeBsdfGlass")
        g.distribution = "SHARP"
        g.inputs["Color"].default_value = (1.0, 1.0, 1.0, 1.0)
        g.inputs["IOR"].default_value = m["ior"]
        links.new(g.outputs[0], out.inputs["Surface"])
    return mat


def sphere(name, center, radius, mat, solid_inside):
    """A true sphere: a one-point cloud (Cycles renders points as spheres), made from one
    vertex by a geometry-nodes modifier. Cycles culls a point's far side, so a ray inside
    one never leaves it: a sphere that rays enter (glass) is instead an icosphere of 327,680
    faces with smooth normals, whose faces stray less than 3e-5 of the radius from the
    sphere."""
    if solid_inside:
        bpy.ops.mesh.primitive_ico_sphere_add(subdivisions=7, radius=radius, location=blender(center))
        obj = bpy.context.active_object
        obj.name = name
        mesh = obj.data
        mesh.polygons.foreach_set("use_smooth", [True] * len(mesh.polygons))
        mesh.materials.append(mat)
        return
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata([blender(center)], [], [])
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(obj)
    tree = bpy.data.node_groups.new(name, "GeometryNodeTree")
    tree.inputs.new("NodeSocketGeometry", "Geometry")
    tree.outputs.new("NodeSocketGeometry", "Geometry")
    gin = tree.nodes.new("NodeGroupInput")
    gout = tree.nodes.new("NodeGroupOutput")
    points = tree.nodes.new("GeometryNodeMeshToPoints")
    points.inputs["Radius"].default_value = radius
    setmat = tree.nodes.new("GeometryNodeSetMaterial")
    setmat.inputs["Material"].default_value = mat
    tree.links.new(gin.outputs[0], points.inputs["Mesh"])
    tree.links.new(points.outputs["Points"], setmat.inputs["Geometry"])
    tree.links.new(setmat.outputs["Geometry"], gout.inputs[0])
    mod = obj.modifiers.new(name, "NODES")
    mod.node_group = tree


def build(o):
    bpy.ops.wm.read_factory_settings(use_empty=True)
    sc = bpy.context.scene
    desc = scenes.SCENES[o["scene"]]
    width, height = (int(x) for x in o["size"].split("x"))

    mats = {}
    for name in {m for m, _ in desc["meshes"]} | {m for m, _, _ in desc["spheres"]}:
        mats[name] = material(name, scenes.MATERIALS[name])
    for k, (m, tris) in enumerate(desc["meshes"]):
        verts = [blender(p) for t in tris for p in t]
        faces = [(3 * i, 3 * i + 1, 3 * i + 2) for i in range(len(tris))]
        mesh = bpy.data.meshes.new("mesh%d" % k)
        mesh.from_pydata(verts, [], faces)
        mesh.materials.append(mats[m])
        obj = bpy.data.objects.new("mesh%d" % k, mesh)
        sc.collection.objects.link(obj)
    for k, (m, c, r) in enumerate(desc["spheres"]):
        sphere("sphere%d" % k, c, r, mats[m], scenes.MATERIALS[m]["kind"] == "glass")

    # camera: crtc's fov is the vertical angle
    cam_desc = desc["camera"]
    cam = bpy.data.cameras.new("camera")
    cam.sensor_fit = "VERTICAL"
    cam.sensor_height = 24.0
    cam.lens = 12.0 / math.tan(math.radians(cam_desc["fov"]) / 2)
    cam.clip_start = 1e-3
    cam.clip_end = 1e6
    cam_obj = bpy.data.objects.new("camera", cam)
    sc.collection.objects.link(cam_obj)
    from mathutils import Vector
    pos, at = Vector(blender(cam_desc["position"])), Vector(blender(cam_desc["look_at"]))
    cam_obj.location = pos
    cam_obj.rotation_euler = (at - pos).to_track_quat("-Z", "Y").to_euler()
    sc.camera = cam_obj

    world = bpy.data.worlds.new("world")
    world.use_nodes = True
    nodes, links = world.node_tree.nodes, world.node_tree.links
    nodes.clear()
    wout = nodes.new("ShaderNodeOutputWorld")
    bg = nodes.new("ShaderNodeBackground")
    links.new(bg.outputs[0], wout.inputs["Surface"])
    bdesc = desc["background"]
    if bdesc["kind"] == "color":
        bg.inputs["Color"].default_value = (*bdesc["color"], 1.0)
        bg.inputs["Strength"].default_value = 1.0
        world.cycles.sampling_method = "NONE"
    else:
        env = nodes.new("ShaderNodeTexEnvironment")
        env.image = bpy.data.images.load(os.path.join(os.path.abspath(o["dir"]), bdesc["image"]))
        env.image.colorspace_settings.name = "Linear"
        env.interpolation = "Linear"
        env.projection = "EQUIRECTANGULAR"
        coord = nodes.new("ShaderNodeTexCoord")
        mapping = nodes.new("ShaderNodeMapping")
        mapping.vector_type = "POINT"
        mapping.inputs["Rotation"].default_value = (0.0, 0.0, SKY_ROTATE_Z)
        links.new(coord.outputs["Generated"], mapping.inputs["Vector"])
        links.new(mapping.outputs["Vector"], env.inputs["Vector"])
        links.new(env.outputs["Color"], bg.inputs["Color"])
        bg.inputs["Strength"].default_value = 1.0
        world.cycles.sampling_method = "MANUAL"
        world.cycles.sample_map_resolution = 1024
    sc.world = world

    r = sc.render
    r.engine = "CYCLES"
    r.resolution_x, r.resolution_y, r.resolution_percentage = width, height, 100
    r.threads_mode = "FIXED"
    r.threads = int(o["threads"])
    r.film_transparent = False
    r.use_persistent_data = False
    r.image_settings.file_format = "OPEN_EXR"
    r.image_settings.color_mode = "RGB"
    r.image_settings.color_depth = "32"
    r.image_settings.exr_codec = "ZIP"
    r.filepath = os.path.abspath(o["out"])
    vs = sc.view_settings
    vs.view_transform = "Standard"
    vs.look = "None"
    vs.exposure = 0.0
    vs.gamma = 1.0

    c = sc.cycles
    c.device = "CPU"
    c.samples = int(o["samples"])
    c.use_adaptive_sampling = float(o["adaptive"]) > 0
    if c.use_adaptive_sampling:
        c.adaptive_threshold = float(o["adaptive"])
        c.adaptive_min_samples = 0  # Cycles' own choice from the threshold
    c.use_denoising = False
    c.seed = int(o["seed"])
    c.use_animated_seed = False
    bounces = max(0, int(o["bounces"]) - 1)
    c.max_bounces = bounces
    c.diffuse_bounces = bounces
    c.glossy_bounces = bounces
    c.transmission_bounces = bounces
    c.volume_bounces = 0
    c.transparent_max_bounces = 8
    c.sample_clamp_direct = 0.0
    c.sample_clamp_indirect = 0.0
    c.blur_glossy = 0.0
    c.caustics_reflective = True
    c.caustics_refractive = True
    c.light_sampling_threshold = 0.0
    c.pixel_filter_type = "BOX"
    c.filter_width = 1.0
    c.film_exposure = 1.0


def main():
    o = options(sys.argv)
    build(o)
    t0 = time.time()
    bpy.ops.render.render(write_still=True)
    print("cycles.py: rendered in %.3f s" % (time.time() - t0))


main()
