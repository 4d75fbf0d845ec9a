#include "stage.inc"
#declare P = pigment { hexagon color rgb <0.9, 0.2, 0.1> color rgb <0.1, 0.8, 0.3> color rgb <0.2, 0.3, 0.9> rotate -90*x scale 0.6 }
Wall(P)
