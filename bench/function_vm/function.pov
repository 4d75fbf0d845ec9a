// Function VM benchmark (see bench/README.md): the same as function.crt.
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
#declare F = function {
    sin(1 * x + 0.7 * y) * cos(0.5 * y - 0.3 * z) / 1 +
    (1 * x - y) * (0.1 * y + z) * 0.01 +
    sin(2 * x + 1.4 * y) * cos(1.0 * y - 0.6 * z) / 2 +
    (2 * x - y) * (0.2 * y + z) * 0.01 +
    sin(3 * x + 2.1 * y) * cos(1.5 * y - 0.9 * z) / 3 +
    (3 * x - y) * (0.3 * y + z) * 0.01 +
    sin(4 * x + 2.8 * y) * cos(2.0 * y - 1.2 * z) / 4 +
    (4 * x - y) * (0.4 * y + z) * 0.01 +
    sin(5 * x + 3.5 * y) * cos(2.5 * y - 1.5 * z) / 5 +
    (5 * x - y) * (0.5 * y + z) * 0.01 +
    sin(6 * x + 4.2 * y) * cos(3.0 * y - 1.8 * z) / 6 +
    (6 * x - y) * (0.6 * y + z) * 0.01 +
    sin(7 * x + 4.9 * y) * cos(3.5 * y - 2.1 * z) / 7 +
    (7 * x - y) * (0.7 * y + z) * 0.01 +
    sin(8 * x + 5.6 * y) * cos(4.0 * y - 2.4 * z) / 8 +
    (8 * x - y) * (0.8 * y + z) * 0.01 +
    sin(9 * x + 6.3 * y) * cos(4.5 * y - 2.7 * z) / 9 +
    (9 * x - y) * (0.9 * y + z) * 0.01 +
    sin(10 * x + 7.0 * y) * cos(5.0 * y - 3.0 * z) / 10 +
    (10 * x - y) * (1.0 * y + z) * 0.01 +
    sin(11 * x + 7.7 * y) * cos(5.5 * y - 3.3 * z) / 11 +
    (11 * x - y) * (1.1 * y + z) * 0.01 +
    sin(12 * x + 8.4 * y) * cos(6.0 * y - 3.6 * z) / 12 +
    (12 * x - y) * (1.2 * y + z) * 0.01
}
plane { -z, -0.3 texture { pigment { function { F(x, y, z) } color_map { Colors } } finish { ambient 0 diffuse 1 } } }
