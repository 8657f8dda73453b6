# SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
# SPDX-License-Identifier: BSD-3-Clause
# Blender's Cycles bake of the mesh pair of BenchNormalMapBaker, for comparing times with
# vtkNormalMapBaker (BENCHMARKS.md, scripts/bench-blender-bake.sh):
#
#   SURFACEDETAIL_BAKE_MESHES=<folder> build/bin/BenchNormalMapBaker
#   blender -b --factory-startup -noaudio --python Testing/Benchmarks/BlenderBake.py -- \
#     <folder> <size> <threads>
#
# A tangent-space normal map of size x size, selected to active (the detailed torus selected,
# the coarse one active), 1 sample, on the CPU with <threads> render threads. Only the bake
# operator is timed: importing the meshes and saving the map are not part of a bake. The map
# is saved as <folder>/blender_<size>.png, to be looked at: a bake that missed the detailed
# mesh gives a flat map in the same time.
#
# Our baker casts each ray both ways along the coarse normal, up to MaxRayDistance (0.2) each
# way, and keeps the hit nearer the coarse surface. Blender casts one ray inward from the
# coarse surface pushed out by the cage extrusion, and keeps the hit nearest that start
# within the maximum ray distance: extrusion 0.2 and distance 0.4 cover the same segment.
# Where the detailed surface crosses a ray twice, Blender keeps the outer crossing and ours the
# one nearer the coarse surface; on this pair (a height field within 0.06 of the coarse torus)
# every ray crosses it once.

import math
import os
import sys
import time

import bpy

REACH = 0.2


def import_obj(path):
    # Blender's importer turns OBJ's Y-up into Z-up unless told the file is Z-up already;
    # keeping VTK's axes makes the two bakes see the same coordinates.
    bpy.ops.wm.obj_import(filepath=path, forward_axis="Y", up_axis="Z")
    obj = bpy.context.selected_objects[0]
    mesh = obj.data
    if not mesh.has_custom_normals:
        sys.exit(f"{path}: the importer kept no normals")
    # Custom split normals count only with auto smooth on (Blender 3.x), on smooth faces.
    mesh.use_auto_smooth = True
    mesh.auto_smooth_angle = math.pi
    mesh.polygons.foreach_set("use_smooth", [True] * len(mesh.polygons))
    mesh.update()
    return obj


def main():
    args = sys.argv[sys.argv.index("--") + 1 :]
    folder, size, threads = args[0], int(args[1]), int(args[2])

    bpy.ops.object.select_all(action="SELECT")
    bpy.ops.object.delete()
    coarse = import_obj(os.path.join(folder, "coarse.obj"))
    detailed = import_obj(os.path.join(folder, "detailed.obj"))

    image = bpy.data.images.new("baked", width=size, height=size, alpha=False)
    image.colorspace_settings.name = "Non-Color"
    material = bpy.data.materials.new("baked")
    material.use_nodes = True
    node = material.node_tree.nodes.new("ShaderNodeTexImage")
    node.image = image
    material.node_tree.nodes.active = node  # the bake writes into the active image node
    coarse.data.materials.clear()
    coarse.data.materials.append(material)

    scene = bpy.context.scene
    scene.render.engine = "CYCLES"
    scene.cycles.device = "CPU"
    scene.cycles.samples = 1
    # With denoising on (the default), a Blender built without OpenImageDenoise (Debian's)
    # stops Cycles before it shades anything: the map comes out uniformly grey. A bake is
    # not denoised anyway.
    scene.cycles.use_denoising = False
    scene.render.threads_mode = "FIXED"
    scene.render.threads = threads

    bpy.ops.object.select_all(action="DESELECT")
    detailed.select_set(True)
    coarse.select_set(True)
    bpy.context.view_layer.objects.active = coarse

    start = time.perf_counter()
    bpy.ops.object.bake(
        type="NORMAL",
        normal_space="TANGENT",
        use_selected_to_active=True,
        cage_extrusion=REACH,
        max_ray_distance=2 * REACH,
        target="IMAGE_TEXTURES",
        use_clear=True,
    )
    seconds = time.perf_counter() - start

    image.filepath_raw = os.path.join(folder, f"blender_{size}.png")
    image.file_format = "PNG"
    image.save()
    print(f"BlenderBake size {size} threads {threads} bake_seconds {seconds:.3f}", flush=True)


main()
