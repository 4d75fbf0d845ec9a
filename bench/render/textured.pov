// Render benchmark: textured (see bench/README.md, "Renderer vs POV-Ray 3.7").
// Equivalent to textured.crt, with POV-Ray's own noise: the same shaded points and shadow
// rays, not the same veins. Shading matched to the CRT formula as in mirror_room.pov.
#version 3.7;
global_settings {
    assumed_gamma 1.0
    ambient_light rgb 0.1
    max_trace_level 4
    adc_bailout 0
}

#declare VFov = 45;
camera {
    perspective
    location <0.0, 2.5, -7.0>
    direction z * 0.5 / tan(radians(VFov / 2))
    up y
    right x * image_width / image_height
    look_at <0.0, 0.8, 0.0>
}

light_source { <-6.0, 8.0, -6.0> color rgb 0.35 }
light_source { <6.0, 8.0, -6.0> color rgb 0.35 }
light_source { <-6.0, 6.0, 6.0> color rgb 0.25 }
light_source { <6.0, 6.0, 6.0> color rgb 0.25 }

background { color rgb <0.55, 0.65, 0.85> }

#declare Flat = finish { ambient 1 diffuse 1 }
#declare Wood = texture {
    pigment { wood turbulence 0.1 color_map { [0 rgb <0.75, 0.5, 0.25>] [1 rgb <0.4, 0.2, 0.08>] } scale 0.3 }
    finish { Flat }
}

plane {
    y, 0
    texture {
        pigment { granite color_map { [0 rgb <0.2, 0.2, 0.22>] [1 rgb <0.8, 0.78, 0.75>] } scale 2 }
        finish { Flat }
    }
}
sphere {
    <-2.2, 1.0, 0.0>, 1.0
    texture {
        pigment {
            marble turbulence 1
            color_map { [0 rgb <0.9, 0.9, 0.85>] [0.6 rgb <0.5, 0.5, 0.55>] [1 rgb <0.1, 0.1, 0.15>] }
        }
        finish { Flat }
    }
}
sphere { <0.0, 1.0, 0.0>, 1.0 texture { Wood } }
sphere {
    <2.2, 1.0, 0.0>, 1.0
    texture { Wood }
    texture {
        pigment {
            leopard
            color_map { [0 rgbt <0.1, 0.05, 0.02, 0>] [0.45 rgbt <0.1, 0.05, 0.02, 1>] [1 rgbt <0, 0, 0, 1>] }
            scale 0.09
        }
        finish { Flat }
    }
}
