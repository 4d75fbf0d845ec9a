#include "stage.inc"
#declare P = pigment { checker color rgb 0.3 color rgb 0.5 scale 1 }
Wall(P)
intersection {
    box { <-1.5, -1.5, -1.5>, <1.5, 1.5, 0> texture { pigment { color rgb <0.9, 0.6, 0.2> } finish { ambient 0 diffuse 1 } } }
    sphere { <0.8, 0.7, -1.6>, 1.3 inverse texture { pigment { color rgb <0.2, 0.5, 0.9> } finish { ambient 0 diffuse 1 } } }
    rotate <20, 25, 0>
}
