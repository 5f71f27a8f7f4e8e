# Blender Cycles baseline for bench/run.sh and bench/error_per_second.sh: builds the same scene
# from Geodesic's JSON (quads and spheres with diffuse / mirror materials, point lights),
# renders it on the CPU with 2 threads, no denoising and no adaptive sampling, and prints
# paths/s. Spheres are Cycles' analytic spheres (a point of a point cloud, made by geometry
# nodes), not meshes; the pixel filter is a 1-px box, as Geodesic's uniform jitter in the pixel.
#   blender -b --factory-startup -P bench/cycles_cornell.py -- SCENE.json SPP [OUT.png|OUT.exr]
#   blender -b --factory-startup -P bench/cycles_cornell.py -- SCENE.json SPP,SPP,... DIR [SEED]
# The second form renders each sample count to DIR/cycles-SPP.exr (linear radiance) and prints
# one line per render: "cycles-render: SPP SECONDS FILE", SECONDS without scene setup.
import json
import math
import os
import sys
import time

import bpy
from mathutils import Matrix, Vector

args = sys.argv[sys.argv.index("--") + 1:]
scene_path = args[0]
series = [int(n) for n in args[1].split(",")]
spp = series[0]
out_path = args[2] if len(args) > 2 else "/tmp/cycles-baseline.png"
seed = int(args[3]) if len(args) > 3 else 0
doc = json.load(open(scene_path))


def rgb(value, default=0.0):
    if value is None:
        value = default
    return list(value) if isinstance(value, list) else [value] * 3


bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene


def make_material(name, m):
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    nodes, links = mat.node_tree.nodes, mat.node_tree.links
    nodes.clear()
    out = nodes.new("ShaderNodeOutputMaterial")
    diffuse = nodes.new("ShaderNodeBsdfDiffuse")
    diffuse.inputs["Color"].default_value = rgb(m.get("diffuse")) + [1]
    shader = diffuse
    mirror = max(rgb(m.get("mirror")))
    if mirror > 0:
        glossy = nodes.new("ShaderNodeBsdfGlossy")
        glossy.inputs["Roughness"].default_value = 0.0
        glossy.inputs["Color"].default_value = [1, 1, 1, 1]
        mix = nodes.new("ShaderNodeMixShader")
        mix.inputs["Fac"].default_value = mirror
        links.new(diffuse.outputs[0], mix.inputs[1])
        links.new(glossy.outputs[0], mix.inputs[2])
        shader = mix
    links.new(shader.outputs[0], out.inputs["Surface"])
    return mat


materials = {name: make_material(name, m) for name, m in doc["materials"].items()}


def add_mesh(name, verts, faces, material):
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata(verts, [], faces)
    obj = bpy.data.objects.new(name, mesh)
    obj.data.materials.append(materials[material])
    scene.collection.objects.link(obj)


def add_sphere(name, center, radius, material):
    """One vertex turned into a point-cloud point, which Cycles intersects as a true sphere."""
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata([(0, 0, 0)], [], [])
    obj = bpy.data.objects.new(name, mesh)
    obj.location = center
    tree = bpy.data.node_groups.new(name, "GeometryNodeTree")
    tree.inputs.new("NodeSocketGeometry", "Geometry")
    tree.outputs.new("NodeSocketGeometry", "Geometry")
    source, sink = tree.nodes.new("NodeGroupInput"), tree.nodes.new("NodeGroupOutput")
    points = tree.nodes.new("GeometryNodeMeshToPoints")
    points.inputs["Radius"].default_value = radius
    paint = tree.nodes.new("GeometryNodeSetMaterial")
    paint.inputs["Material"].default_value = materials[material]
    tree.links.new(source.outputs[0], points.inputs["Mesh"])
    tree.links.new(points.outputs["Points"], paint.inputs["Geometry"])
    tree.links.new(paint.outputs["Geometry"], sink.inputs[0])
    obj.modifiers.new("sphere", "NODES").node_group = tree
    scene.collection.objects.link(obj)


for i, o in enumerate(doc["objects"]):
    if o["type"] == "quad":
        c, u, v = Vector(o["corner"]), Vector(o["edge_u"]), Vector(o["edge_v"])
        add_mesh(f"quad{i}", [c, c + u, c + u + v, c + v], [(0, 1, 2, 3)], o["material"])
    elif o["type"] == "sphere":
        add_sphere(f"sphere{i}", o["center"], o["radius"], o["material"])
    else:
        raise SystemExit(f"cycles_cornell.py: object type {o['type']} not supported")

for i, l in enumerate(doc.get("lights", [])):
    light = bpy.data.lights.new(f"light{i}", "POINT")
    light.shadow_soft_size = 0.0
    # Blender's point light power P [W] gives radiant intensity P / (4 pi).
    light.energy = 4 * math.pi * max(rgb(l["intensity"]))
    obj = bpy.data.objects.new(f"light{i}", light)
    obj.location = l["position"]
    scene.collection.objects.link(obj)

cam = doc["camera"]
camera = bpy.data.objects.new("camera", bpy.data.cameras.new("camera"))
camera.location = cam["position"]
direction = Vector(cam["look_at"]) - Vector(cam["position"])
camera.rotation_euler = direction.to_track_quat("-Z", "Y").to_euler()
camera.data.sensor_fit = "VERTICAL"
camera.data.angle_y = math.radians(cam.get("fov_y", 45))
scene.collection.objects.link(camera)
scene.camera = camera

render = doc.get("render", {})
scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.render.threads_mode = "FIXED"
scene.render.threads = 2
scene.cycles.use_adaptive_sampling = False
scene.cycles.use_denoising = False
scene.cycles.seed = seed
# Unbiased as Geodesic is: no sample clamping (Cycles clamps indirect light at 10 by default)
# and no glossy filter (which roughens a mirror seen after a diffuse bounce, so that light
# sampling finds the point light's caustics through it: 2.8 % more light in cornell-shared).
scene.cycles.sample_clamp_direct = 0.0
scene.cycles.sample_clamp_indirect = 0.0
scene.cycles.blur_glossy = 0.0
scene.cycles.pixel_filter_type = "BOX"
scene.cycles.filter_width = 1.0
scene.view_settings.view_transform = "Standard"
depth = render.get("max_depth", 5)
scene.cycles.max_bounces = depth
scene.cycles.diffuse_bounces = depth
scene.cycles.glossy_bounces = depth
# Cycles ends paths early by Russian roulette after min_light_bounces; FULL_DEPTH=1 in the
# environment sets it to the depth, so every path runs to full depth as in Geodesic's paper mode.
if os.environ.get("FULL_DEPTH") == "1":
    scene.cycles.min_light_bounces = depth
scene.render.resolution_x = render.get("width", 512)
scene.render.resolution_y = render.get("height", 512)
scene.render.resolution_percentage = 100
scene.render.filepath = out_path
if out_path.endswith(".exr") or len(series) > 1:
    scene.render.image_settings.file_format = "OPEN_EXR"
    scene.render.image_settings.color_depth = "32"


def timed_render(samples):
    scene.cycles.samples = samples
    start = time.time()
    bpy.ops.render.render(write_still=True)
    return time.time() - start


# Marginal throughput: a 1-sample render measures scene sync and BVH build, which the
# spp-sample render also pays; their difference is the time spent tracing spp - 1 samples.
# The process's first render also pays what only a first render does (loading kernels, first
# allocations): 0.09 s at 128x128 where the next 1-sample render takes 0.04 s. Taken as the
# setup, it was subtracted from renders that never paid it, and 0.055 s of their samples' time
# went uncounted (15 % of 16 samples at 128x128). It is a warm-up; the setup is the second.
timed_render(1)
setup = timed_render(1)
if len(series) > 1 or os.path.isdir(out_path):
    for n in series:
        scene.render.filepath = os.path.join(out_path, f"cycles-{n}.exr")
        seconds = timed_render(n)
        # The time of all n samples, the one the 1-sample render held included: its image's
        # error is that of n samples.
        print(f"cycles-render: {n} {(seconds - setup) * n / max(n - 1, 1):.4f} "
              f"{scene.render.filepath}")
    sys.exit(0)
seconds = timed_render(spp)
pixels = scene.render.resolution_x * scene.render.resolution_y
print(f"cycles: {spp} spp at {scene.render.resolution_x}x{scene.render.resolution_y}, "
      f"depth {depth}, in {seconds:.2f} s ({setup:.2f} s for 1 spp): "
      f"{(spp - 1) * pixels / (seconds - setup) / 1e6:.3f} M paths/s")
