// Render benchmark: functions (see bench/README.md, "Renderer vs POV-Ray 3.7").
// Equivalent to functions.crt. Shading matched to the CRT formula as in mirror_room.pov;
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
    look_at <0.0, 1.0, 0.0>
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
isosurface { function { sqrt(pow(sqrt(x * x + z * z) - 0.8, 2.0) + y * y) - 0.3 }
             contained_by { box { <-1.2, -0.4, -1.2>, <1.2, 0.4, 1.2> } }
             Shiny(<0.9, 0.5, 0.2>) rotate <-60, 0, 0> translate <-2.6, 1.3, -0.5> }
isosurface { function { sqrt(x * x + y * y + z * z) - 0.9 + 0.1 * sin(6.0 * x) * sin(6.0 * y) * sin(6.0 * z) }
             contained_by { box { <-1.2, -1.2, -1.2>, <1.2, 1.2, 1.2> } } max_gradient 2.5
             Shiny(<0.3, 0.6, 0.9>) translate <0.0, 1.0, -0.8> }
isosurface { function { y - 0.3 * sin(3.0 * x) * cos(3.0 * z) }
             contained_by { box { <-1, -0.5, -1>, <1, 0.5, 1> } } max_gradient 1.8
             Shiny(<0.3, 0.85, 0.4>) rotate <0, 25, 0> translate <2.6, 0.5, -0.5> }
// POV-Ray samples its function at (x, y) with y running against z: y = 1 - z.
height_field { function 200, 200 { 0.5 * sin(3.14159265 * x) * sin(3.14159265 * (1 - y)) * (0.6 + 0.4 * cos(9.0 * x * (1 - y))) }
               smooth Shiny(<0.8, 0.2, 0.15>)
               translate <-0.5, 0, -0.5> scale <6.0, 1.5, 3.0> translate <0, 0, 2.5> }
