#include "stage.inc"
#declare P = pigment { checker color rgb 0.3 color rgb 0.5 scale 1 }
Wall(P)
#declare Red = texture { pigment { color rgb <0.9, 0.3, 0.2> } finish { ambient 0 diffuse 1 } }
#declare Blue = texture { pigment { color rgb <0.3, 0.4, 0.95> } finish { ambient 0 diffuse 1 } }
#declare Green = texture { pigment { color rgb <0.3, 0.85, 0.4> } finish { ambient 0 diffuse 1 } }
isosurface { function { sqrt(pow(sqrt(x * x + z * z) - 0.8, 2) + y * y) - 0.3 }
             contained_by { box { <-1.2, -0.4, -1.2>, <1.2, 0.4, 1.2> } }
             texture { Red } rotate <-60, 0, 0> translate <-1.3, 1.1, -1> }
isosurface { function { sqrt(x * x + y * y + z * z) - 0.9 + 0.1 * sin(6 * x) * sin(6 * y) * sin(6 * z) }
             contained_by { box { <-1.2, -1.2, -1.2>, <1.2, 1.2, 1.2> } } max_gradient 2.5
             texture { Blue } translate <1.3, 1.1, -1> }
isosurface { function { y - 0.3 * sin(3 * x) * cos(3 * z) }
             contained_by { box { <-1, -0.5, -1>, <1, 0.5, 1> } } max_gradient 1.8
             texture { Green } rotate <-30, 25, 0> translate <0, -1.3, -1> }
