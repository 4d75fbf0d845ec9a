#include "stage.inc"
#declare P = pigment { checker color rgb 0.3 color rgb 0.5 scale 1 }
Wall(P)
#declare Red = texture { pigment { color rgb <0.9, 0.3, 0.2> } finish { ambient 0 diffuse 1 } }
#declare Green = texture { pigment { color rgb <0.3, 0.9, 0.3> } finish { ambient 0 diffuse 1 } }
#declare Blue = texture { pigment { color rgb <0.3, 0.4, 0.95> } finish { ambient 0 diffuse 1 } }
sphere_sweep { linear_spline 4, <-2.6, 1.2, -1>, 0.15, <-1.6, 2.4, -1.5>, 0.5, <-0.4, 1.4, -1>, 0.25,
               <0.6, 2.6, -0.5>, 0.05 texture { Red } }
sphere_sweep { cubic_spline 6, <-3, -1, -1>, 0.2, <-2.4, 0.2, -1>, 0.2, <-1.2, -1.4, -1.5>, 0.35,
               <0, 0.4, -1>, 0.15, <1.2, -1.2, -0.5>, 0.3, <2, 0, -1>, 0.2 texture { Green } }
sphere_sweep { b_spline 7, <1, 1, 0>, 0.2, <2.2, 2.4, -1>, 0.25, <2.8, 1, -2>, 0.3, <1.6, 0, -1>, 0.25,
               <2.4, -1.4, 0>, 0.2, <2.9, -2.2, -1>, 0.25, <1.4, -2.6, -2>, 0.2 texture { Blue } }
