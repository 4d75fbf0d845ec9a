#include "stage.inc"
#declare P = pigment { checker color rgb 0.3 color rgb 0.5 scale 1 }
Wall(P)
#declare Red = texture { pigment { color rgb <0.9, 0.3, 0.2> } finish { ambient 0 diffuse 1 } }
#declare Green = texture { pigment { color rgb <0.3, 0.9, 0.3> } finish { ambient 0 diffuse 1 } }
#declare Blue = texture { pigment { color rgb <0.3, 0.4, 0.95> } finish { ambient 0 diffuse 1 } }
sor { 7, <0.3, -0.2>, <0.5, 0>, <0.8, 0.4>, <0.4, 1>, <0.35, 1.3>, <0.6, 1.6>, <0.7, 1.8>
      texture { Red } rotate <-25, 0, 15> translate <-1.8, 0.2, -1> }
sor { 7, <0, -0.1>, <0.6, 0>, <0.1, 0.2>, <0.1, 0.8>, <0.7, 1.2>, <0.8, 1.6>, <0.9, 1.8> open
      texture { Green } rotate <-50, 0, -10> translate <1.6, 0.3, -1> }
sor { 5, <0.2, -0.5>, <0.05, 0>, <0.6, 0.6>, <0.05, 1.4>, <0.3, 1.8>
      texture { Blue } rotate <-20, 0, 70> translate <0.8, -2, -1> }
