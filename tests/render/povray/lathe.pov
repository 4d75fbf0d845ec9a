#include "stage.inc"
#declare P = pigment { checker color rgb 0.3 color rgb 0.5 scale 1 }
Wall(P)
#declare Red = texture { pigment { color rgb <0.9, 0.3, 0.2> } finish { ambient 0 diffuse 1 } }
#declare Green = texture { pigment { color rgb <0.3, 0.9, 0.3> } finish { ambient 0 diffuse 1 } }
#declare Blue = texture { pigment { color rgb <0.3, 0.4, 0.95> } finish { ambient 0 diffuse 1 } }
#declare Yellow = texture { pigment { color rgb <0.9, 0.8, 0.2> } finish { ambient 0 diffuse 1 } }
lathe { linear_spline 7, <0, 0>, <0.8, 0>, <0.8, 0.2>, <0.2, 0.4>, <0.2, 1>, <0.7, 1.3>, <0, 1.4>
        texture { Red } rotate <-30, 0, 15> translate <-1.7, 0.4, -1> }
lathe { quadratic_spline 6, <0.5, -0.2>, <0, 0>, <0.6, 0.2>, <0.5, 0.9>, <0.2, 1.3>, <0, 1.5>
        texture { Green } rotate <-40, 0, -20> translate <1.5, 0.5, -1> }
lathe { cubic_spline 7, <0.6, 0.2>, <0.9, 0.5>, <0.6, 0.8>, <0.3, 0.5>, <0.6, 0.2>, <0.9, 0.5>, <0.6, 0.8>
        texture { Blue } rotate <-60, 0, 10> translate <-1.4, -2, -1> }
lathe { bezier_spline 8, <0, 0>, <0.5, 0>, <0.9, 0.3>, <0.7, 0.6>, <0.7, 0.6>, <0.5, 0.9>, <0.3, 1>, <0, 1>
        texture { Yellow } rotate <-25, 0, -30> translate <1.4, -2.2, -1> }
