// Render benchmark: csg (see bench/README.md, "Renderer vs POV-Ray 3.7").
// Equivalent to csg.crt. Shading matched to the CRT formula as in
// mirror_room.pov; recursiondepth 3 -> max_trace_level 4. Each CSG operand
// carries its own texture, so cut faces show the subtracted solid's texture.
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
    location <-0.4, 3.5, -7.5>
    direction z * 0.5 / tan(radians(VFov / 2))
    up y
    right x * image_width / image_height
    look_at <-0.4, 1.0, 0.4>
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

difference {
    box { <-3.2, 0.0, -1.0>, <-0.8, 2.4, 1.4> Shiny(<0.8, 0.2, 0.15>) }
    sphere { <-1.4, 2.0, -0.6>, 1.3 Shiny(<0.95, 0.8, 0.2>) }
}

#declare R = 1.4;
#declare D = 0.75;
#declare C = <2.0, 1.2, 0.2>;
intersection {
    sphere { C + <D, 0, 0>, R Shiny(<0.2, 0.5, 0.9>) }
    sphere { C - <D, 0, 0>, R Shiny(<0.2, 0.8, 0.3>) }
    sphere { C - <0, D, 0>, R Shiny(<0.9, 0.9, 0.9>) }
    sphere { C + <0, 0, D>, R Shiny(<0.7, 0.3, 0.8>) }
}
