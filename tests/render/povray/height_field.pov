#include "stage.inc"
#declare P = pigment { checker color rgb 0.3 color rgb 0.5 scale 1 }
Wall(P)
#declare Red = texture { pigment { color rgb <0.9, 0.3, 0.2> } finish { ambient 0 diffuse 1 } }
#declare Blue = texture { pigment { color rgb <0.3, 0.4, 0.95> } finish { ambient 0 diffuse 1 } }
height_field { png "height_field.png" smooth
               texture { Red } translate <-0.5, 0, -0.5> scale <2.2, 0.8, 2.2> rotate <-65, 20, 0> translate <-1.2, 0.2, -1> }
// POV-Ray samples its function at (x, y) with y running against z: y = 1 - z.
height_field { function 30, 30 { 0.6 * sin(3.14159265 * x) * sin(3.14159265 * (1 - y)) * (0.6 + 0.4 * cos(9 * x * (1 - y))) }
               texture { Blue } translate <-0.5, 0, -0.5> scale <2.2, 1, 2.2> rotate <-50, -25, 0> translate <1.2, -0.3, -1> }
