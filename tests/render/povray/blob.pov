#include "stage.inc"
#declare P = pigment { checker color rgb 0.3 color rgb 0.5 scale 1 }
Wall(P)
#declare Red = texture { pigment { color rgb <0.9, 0.3, 0.2> } finish { ambient 0 diffuse 1 } }
#declare Blue = texture { pigment { color rgb <0.3, 0.4, 0.95> } finish { ambient 0 diffuse 1 } }
blob { threshold 0.5
       sphere { <-0.6, 0, 0>, 1, 1 }
       sphere { <0.6, 0, 0>, 1, 1 }
       cylinder { <0, -1, 0>, <0, 1.2, 0.3>, 0.5, 1.2 }
       sphere { <0.3, 0.3, -0.6>, 0.5, -1 }
       texture { Red } rotate <-20, 30, 0> translate <-1.5, 1.1, -1> }
blob { threshold 0.3
       cylinder { <-1, 0, 0>, <0, 0.8, 0>, 0.45, 1 }
       cylinder { <0, 0.8, 0>, <1, 0, 0.5>, 0.45, 1 }
       cylinder { <1, 0, 0.5>, <1.5, -0.8, 0>, 0.35, 2 }
       texture { Blue } rotate <30, -10, 15> translate <0.8, -1.6, -1> }
