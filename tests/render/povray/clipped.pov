#include "stage.inc"
#declare P = pigment { checker color rgb 0.3 color rgb 0.5 scale 1 }
Wall(P)
#declare Red = texture { pigment { color rgb <0.9, 0.3, 0.2> } finish { ambient 0 diffuse 1 } }
#declare Blue = texture { pigment { color rgb <0.3, 0.4, 0.95> } finish { ambient 0 diffuse 1 } }
#declare Green = texture { pigment { color rgb <0.3, 0.85, 0.4> } finish { ambient 0 diffuse 1 } }
sphere { <0, 0, 0>, 1 clipped_by { box { <-2, -2, -2>, <2, 0.4, 2> } }
         texture { Red } rotate <-50, 20, 0> translate <-1.4, 1.1, -1> }
// crt's plane is the half-space behind its normal: POV-Ray's plane { x, 0.2 }.
torus { 0.9, 0.3 clipped_by { plane { x, 0.2 } }
        texture { Blue } rotate <-70, 0, 0> translate <1.4, 1.1, -1> }
cylinder { <0, -1, 0>, <0, 1, 0>, 0.6 open clipped_by { sphere { <0.3, 0.2, 0>, 0.9 } }
           texture { Green } rotate <-30, 0, 20> translate <0, -1.3, -1> }
