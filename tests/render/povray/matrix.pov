#include "stage.inc"
#declare P = pigment { checker color rgb <0.9, 0.6, 0.1> color rgb <0.1, 0.3, 0.8> scale 0.7
                       matrix <1, 0.4, 0,  0.6, 1, 0,  0, 0, 1,  0.25, -0.1, 0> }
Wall(P)
