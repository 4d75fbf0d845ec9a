#include "stage.inc"
#declare P = pigment { checker color rgb 0.3 color rgb 0.5 scale 1 }
Wall(P)
#declare Red = texture { pigment { color rgb <0.9, 0.3, 0.2> } finish { ambient 0 diffuse 1 } }
#declare Green = texture { pigment { color rgb <0.3, 0.9, 0.3> } finish { ambient 0 diffuse 1 } }
#declare Blue = texture { pigment { color rgb <0.3, 0.4, 0.95> } finish { ambient 0 diffuse 1 } }
#macro Around(N, Radius, Inner, I)
    #local R = (mod(I, 2) = 0 ? Radius : Inner);
    <R * cos(radians(I * 360 / N)), R * sin(radians(I * 360 / N))>
#end
prism { linear_sweep linear_spline -0.3, 0.3, 10,
        <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1>,
        <-0.5, -0.5>, <0.5, -0.5>, <0.5, 0.5>, <-0.5, 0.5>, <-0.5, -0.5>
        texture { Red } scale 0.9 rotate <-60, 20, 0> translate <1.7 * -1, 1.5, -1> }
prism { linear_sweep quadratic_spline -0.4, 0.4, 8,
        Around(6, 1, 1, 5)
        #for (I, 0, 5) Around(6, 1, 1, I) #end
        Around(6, 1, 1, 0)
        texture { Green } scale 0.9 rotate <-50, -30, 0> translate <1.7, 1.5, -1> }
prism { linear_sweep cubic_spline -0.3, 0.3, 13,
        Around(10, 1, 0.55, 9)
        #for (I, 0, 9) Around(10, 1, 0.55, I) #end
        Around(10, 1, 0.55, 0) Around(10, 1, 0.55, 1)
        texture { Blue } scale 1.1 rotate <-65, 10, 0> translate <-1.6, -1.6, -1> }
prism { linear_sweep bezier_spline -0.3, 0.3, 16,
        <0, -1>, <0.9, -1>, <1, -0.4>, <1, 0>,
        <1, 0>, <1, 1.1>, <0.2, 0.6>, <0, 1>,
        <0, 1>, <-0.2, 0.6>, <-1, 1.1>, <-1, 0>,
        <-1, 0>, <-1, -0.4>, <-0.9, -1>, <0, -1>
        texture { Red } scale 0.9 rotate <-55, -25, 0> translate <1.7, -1.6, -1> }
prism { conic_sweep linear_spline 0, 1, 4, <-0.5, -0.5>, <0.5, -0.5>, <0, 0.6>, <-0.5, -0.5>
        texture { Green } scale 1.2 rotate <200, 30, 0> translate <0, 0.6, -1.5> }
