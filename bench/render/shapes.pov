// Render benchmark: shapes (see bench/README.md, "Renderer vs POV-Ray 3.7").
// Equivalent to shapes.crt. Shading matched to the CRT formula as in mirror_room.pov;
// recursiondepth 3 -> max_trace_level 4.
#version 3.7;
global_settings {
    assumed_gamma 1.0
    ambient_light rgb 0.1
    max_trace_level 4
    adc_bailout 0
}

#declare VFov = 42;
camera {
    perspective
    location <0.0, 3.2, -8.0>
    direction z * 0.5 / tan(radians(VFov / 2))
    up y
    right x * image_width / image_height
    look_at <0.0, 1.2, 0.0>
}

light_source { <-4.0, 8.0, -6.0> color rgb 1 }

background { color rgb <0.3, 0.35, 0.45> }

#macro Shiny(C)
    texture { pigment { color rgb C } finish { ambient 1 diffuse 1 phong 0.5 phong_size 20 } }
#end

plane {
    y, 0
    // kr 0.3 -> kd 0.7, ambient 0.7
    texture { pigment { color rgb 0.6 } finish { ambient 0.7 diffuse 0.7 reflection { 0.3 } } }
}

text { ttf "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf" "Shapes, 3D!" 0.3, 0
       Shiny(<0.9, 0.5, 0.2>) scale 1.2 translate <-3.4, 2.6, 1.5> }
blob { threshold 0.5
       sphere { <-0.6, 0, 0>, 1, 1 }
       sphere { <0.6, 0, 0>, 1, 1 }
       cylinder { <0, -1, 0>, <0, 1.2, 0.3>, 0.5, 1.2 }
       sphere { <0.3, 0.3, -0.6>, 0.5, -1 }
       Shiny(<0.3, 0.6, 0.9>) translate <-2.6, 1.0, -0.5> }
lathe { linear_spline 8, <0, 0>, <0.5, 0>, <0.7, 0.4>, <0.35, 1.2>, <0.5, 1.8>, <0.45, 1.8>,
        <0.3, 1.25>, <0, 1.25>
        Shiny(<0.8, 0.2, 0.15>) translate <-0.4, 0, -1.0> }
sor { 8, <0, -0.1>, <0.6, 0>, <0.15, 0.2>, <0.12, 0.5>, <0.15, 0.8>, <0.7, 1.2>, <0.8, 1.6>,
      <0.9, 1.8> open
      Shiny(<0.95, 0.8, 0.2>) translate <1.2, 0, -1.2> }
prism { bezier_spline 0, 0.6, 8, <0, -1>, <1.2, -1>, <1, 1>, <0, 1>, <0, 1>, <-1, 1>,
        <-1.2, -1>, <0, -1>
        Shiny(<0.2, 0.8, 0.3>) translate <3.0, 0, 0> }
