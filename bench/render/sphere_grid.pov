// Render benchmark: sphere_grid (see bench/README.md, "Renderer vs POV-Ray 3.7").
// Equivalent to sphere_grid.crt. Shading matched to the CRT formula as in
// mirror_room.pov; CRT specular ks / shininess sh (Phong, r.v) -> phong ks
// phong_size sh; recursiondepth 3 -> max_trace_level 4.
#version 3.7;
global_settings {
    assumed_gamma 1.0
    ambient_light rgb 0.15
    max_trace_level 4
    adc_bailout 0
}

#declare VFov = 45;
camera {
    perspective
    location <0.0, 6.0, -12.0>
    direction z * 0.5 / tan(radians(VFov / 2))
    up y
    right x * image_width / image_height
    look_at <0.0, 0.0, 25.0>
}

light_source { <-30.0, 60.0, -40.0> color rgb 1 }

background { color rgb <0.55, 0.65, 0.85> }

plane {
    y, 0
    texture { pigment { color rgb <0.8, 0.8, 0.75> } finish { ambient 1 diffuse 1 } }
}

#for (I, 0, 99)
    #for (J, 0, 99)
        sphere {
            <I - 49.5, 0.4, J * 1.0>, 0.4
            texture {
                pigment { color rgb <0.2 + 0.7 * I / 99.0, 0.3 + 0.4 * mod(I + J, 3) / 2.0, 0.9 - 0.7 * J / 99.0> }
                // kd = 1 - kr = 0.8; ambient = kd
                finish { ambient 0.8 diffuse 0.8 reflection { 0.2 } phong 0.6 phong_size 40 }
            }
        }
    #end
#end
