// Render benchmark: mirror_room (see bench/README.md, "Renderer vs POV-Ray 3.7").
// Equivalent to mirror_room.crt; the shading is matched to the CRT formula
// (language.md section 6):
//   CRT ambient A*C*kd      -> ambient_light A, finish ambient kd
//   CRT diffuse kd (Lambert) -> finish diffuse kd (brilliance 1)
//   CRT reflectivity kr      -> reflection kr (not metallic, no fresnel)
//   CRT recursiondepth 10    -> max_trace_level 11 (POV-Ray counts the camera
//                               ray as a level); adc_bailout 0 so that POV-Ray
//                               traces every level as crtc does
//   CRT vertical fov F       -> direction of length 0.5 / tan(F/2), up y,
//                               right x * width / height (pixel centres as crtc)
#version 3.7;
global_settings {
    assumed_gamma 1.0
    ambient_light rgb 0.1
    max_trace_level 11
    adc_bailout 0
}

#declare VFov = 90;
camera {
    perspective
    location <0.5, 0.5, -0.3>
    direction z * 0.5 / tan(radians(VFov / 2))
    up y
    right x * image_width / image_height
    look_at <0.0, 0.5, 1.0>
}

light_source { <1.0, 2.0, -1.0> color rgb 1 }

// kd = 1 - kr, ambient = kd (CRT scales the global ambient by kd)
#macro Mat(C, Kr)
    texture {
        pigment { color rgb C }
        finish { ambient 1 - Kr diffuse 1 - Kr reflection { Kr } }
    }
#end

#declare Mirror = Mat(<1.0, 1.0, 1.0>, 0.93)

sphere { <-1.0, 0.0, 1.0>, 0.5 Mat(<0.5, 0.5, 0.5>, 0.65) }
// floor, ceiling
plane { y, -0.5 Mat(<0.5, 0.5, 0.5>, 0) }
plane { -y, -2.5 Mat(<0.0, 0.5, 0.0>, 0) }
// back and front mirrors
plane { -z, -3.0 texture { Mirror } }
plane { z, -1.1 texture { Mirror } }
// right and left walls
plane { -x, -1.7 Mat(<0.5, 0.0, 0.0>, 0) }
plane { x, -1.7 Mat(<0.0, 0.0, 0.5>, 0) }
