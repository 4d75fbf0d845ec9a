#include "stage.inc"
#declare P = pigment { checker color rgb <0.9, 0.6, 0.1> color rgb <0.1, 0.3, 0.8> scale 0.7 }
Wall(P)
