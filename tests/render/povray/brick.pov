#include "stage.inc"
#declare P = pigment { brick color rgb <0.8, 0.8, 0.7> color rgb <0.6, 0.2, 0.1> brick_size <1.2, 0.5, 0.9> mortar 0.08 }
Wall(P)
