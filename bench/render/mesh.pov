// Render benchmark: mesh (see bench/README.md, "Renderer vs POV-Ray 3.7").
// Equivalent to mesh.crt; the terrain is gen_terrain.py's mesh2 of the same triangles.
#version 3.7;
global_settings {
    assumed_gamma 1.0
    ambient_light rgb 0.1
    max_trace_level 4
    adc_bailout 0
}

#declare VFov = 50;
camera {
    perspective
    location <0.0, 3.0, -6.5>
    direction z * 0.5 / tan(radians(VFov / 2))
    up y
    right x * image_width / image_height
    look_at <0.0, 0.0, 0.0>
}

light_source { <-6.0, 7.0, -3.0> color rgb 1 }

background { color rgb <0.5, 0.6, 0.75> }

#include "generated/terrain.inc"
object { Terrain
         texture { pigment { color rgb <0.45, 0.6, 0.3> } finish { ambient 1 diffuse 1 phong 0.2 phong_size 10 } } }
