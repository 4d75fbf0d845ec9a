// Function VM benchmark (see bench/README.md): the same as plain.crt.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light 0 }
camera {
    perspective
    location <0, 0, -10>
    direction z * 0.5 / tan(radians(40 / 2))
    up y
    right x * image_width / image_height
    look_at <0, 0, 0>
}
light_source { <0, 0, -10> color rgb 1 parallel point_at <0, 0, 0> }
background { color rgb 0 }
#declare Colors = color_map { [0 rgb <0.9, 0.2, 0.1>] [0.5 rgb <0.1, 0.8, 0.3>] [1 rgb <0.2, 0.3, 0.9>] }
plane { -z, -0.3 texture { pigment { gradient x color_map { Colors } } finish { ambient 0 diffuse 1 } } }
