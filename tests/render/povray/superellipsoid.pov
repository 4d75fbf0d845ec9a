#include "stage.inc"
#declare P = pigment { checker color rgb 0.3 color rgb 0.5 scale 1 }
Wall(P)
#macro Flat(C) texture { pigment { color rgb C } finish { ambient 0 diffuse 1 } } #end
superellipsoid { <0.25, 0.25> Flat(<0.9, 0.3, 0.2>) scale 0.9 rotate <30, 40, 0> translate <-1.7, 1.5, -1> }
superellipsoid { <1, 0.4> Flat(<0.3, 0.9, 0.3>) scale 0.9 rotate <60, 20, 0> translate <1.7, 1.5, -1> }
superellipsoid { <2.5, 3> Flat(<0.3, 0.4, 0.95>) scale 1.2 rotate <20, 30, 10> translate <-1.6, -1.6, -1> }
superellipsoid { <1, 1> Flat(<0.9, 0.3, 0.2>) scale <1, 0.6, 0.8> rotate <10, 70, 0> translate <1.7, -1.6, -1> }
