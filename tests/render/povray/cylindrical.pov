#include "stage.inc"
#declare P = pigment { cylindrical color_map { TwinColors } rotate -90*x scale 3 }
Wall(P)
