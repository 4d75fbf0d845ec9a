#include "stage.inc"
#declare P = pigment { checker color rgb 0.3 color rgb 0.5 scale 1 }
Wall(P)
#declare C = <0.2, 0.1, -1>;
#declare N0 = <0, 0, -1>;
#declare Corners = array[4] { <-2.4, -2.2, -1>, <2.3, -2.4, -1>, <2.2, 2.5, -1>, <-2.5, 2.1, -1> }
#declare Normals = array[4] { <-0.6, -0.5, -1>, <0.7, -0.4, -1>, <0.5, 0.6, -1>, <-0.4, 0.8, -1> }
#for (I, 0, 3)
    #declare J = mod(I + 1, 4);
    smooth_triangle { C, N0, Corners[I], Normals[I], Corners[J], Normals[J]
                      texture { pigment { color rgb <0.9, 0.7, 0.3> } finish { ambient 0 diffuse 1 } } }
#end
