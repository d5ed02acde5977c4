"""Renders a pole on a plane lit only by a clearsky skydome, inside Blender (docs/renderers.md,
"Blender"), and reports the direction of the pole's shadow.

    blender -b --factory-startup --python blender_sun_shadow.py -- SKY.exr OUT.exr SIZE SAMPLES

SKY.exr is a GET /v1/skydome answer with projection=latlong (sun=disc for a hard shadow). The
world follows the recipe of docs/renderers.md: Blender's +Y is North and +X East, and the
Environment Texture is looked up through a Mapping node turned -90 degrees about Z. The camera
looks straight down (orthographic, image up = North). Prints one JSON line: the shadow's
azimuth (degrees clockwise from North, from the pole's foot to the centroid of the shadow's
pixels), the number of shadow pixels and the render time."""

import json
import math
import sys
import time

import bpy

args = sys.argv[sys.argv.index("--") + 1:]
sky_path, out_path, size, samples = args[0], args[1], int(args[2]), int(args[3])

bpy.ops.wm.read_factory_settings(use_empty=True)
scene = bpy.context.scene
scene.render.engine = "CYCLES"
scene.cycles.device = "CPU"
scene.cycles.samples = samples
scene.cycles.use_denoising = False
scene.cycles.max_bounces = 2
scene.render.threads_mode = "FIXED"
scene.render.threads = 2
scene.render.resolution_x = size
scene.render.resolution_y = size
scene.render.resolution_percentage = 100
scene.render.image_settings.file_format = "OPEN_EXR"
scene.render.image_settings.color_depth = "32"
scene.view_settings.view_transform = "Standard"

# The world: the skydome, turned so that Blender's +Y is North (docs/renderers.md).
world = bpy.data.worlds.new("clearsky")
scene.world = world
world.use_nodes = True
nodes = world.node_tree.nodes
links = world.node_tree.links
nodes.clear()
coordinates = nodes.new("ShaderNodeTexCoord")
mapping = nodes.new("ShaderNodeMapping")
mapping.inputs["Rotation"].default_value = (0.0, 0.0, math.radians(-90.0))
environment = nodes.new("ShaderNodeTexEnvironment")
environment.image = bpy.data.images.load(sky_path)
environment.interpolation = "Closest"  # the sun's disc stays in its pixels
background = nodes.new("ShaderNodeBackground")
output = nodes.new("ShaderNodeOutputWorld")
links.new(coordinates.outputs["Generated"], mapping.inputs["Vector"])
links.new(mapping.outputs["Vector"], environment.inputs["Vector"])
links.new(environment.outputs["Color"], background.inputs["Color"])
links.new(background.outputs["Background"], output.inputs["Surface"])
# Importance sampling of the map at its own resolution finds the sun's few pixels.
world.cycles.sampling_method = "MANUAL"
world.cycles.sample_map_resolution = environment.image.size[0]

# A plane and a pole 1.5 m high at the origin.
bpy.ops.mesh.primitive_plane_add(size=8.0, location=(0.0, 0.0, 0.0))
bpy.ops.mesh.primitive_cylinder_add(radius=0.05, depth=1.5, location=(0.0, 0.0, 0.75))

camera_data = bpy.data.cameras.new("top")
camera_data.type = "ORTHO"
camera_data.ortho_scale = 5.0
camera = bpy.data.objects.new("top", camera_data)
camera.location = (0.0, 0.0, 10.0)  # looking down -Z, image up = +Y = North
scene.collection.objects.link(camera)
scene.camera = camera

scene.render.filepath = out_path
started = time.time()
bpy.ops.render.render(write_still=True)
render_s = time.time() - started

image = bpy.data.images.load(out_path)
w, h = image.size
pixels = list(image.pixels)  # RGBA, rows from the bottom (+Y = North up)
luminance = [0.2126 * pixels[4 * i] + 0.7152 * pixels[4 * i + 1] + 0.0722 * pixels[4 * i + 2]
             for i in range(w * h)]
lit = sorted(luminance)[len(luminance) // 2]
metres_per_pixel = 5.0 / w
sum_x = sum_y = 0.0
count = 0
for j in range(h):
    for i in range(w):
        x = (i + 0.5 - w / 2) * metres_per_pixel  # East
        y = (j + 0.5 - h / 2) * metres_per_pixel  # North
        if math.hypot(x, y) < 0.1:  # the pole itself, seen from above
            continue
        if luminance[j * w + i] < 0.35 * lit:
            sum_x += x
            sum_y += y
            count += 1
azimuth = math.degrees(math.atan2(sum_x, sum_y)) % 360.0 if count else float("nan")
print("CLEARSKY_SHADOW " + json.dumps({"shadow_azimuth_deg": azimuth, "shadow_pixels": count,
                                        "lit_luminance": lit, "render_s": render_s}))
