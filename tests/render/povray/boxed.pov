#include "stage.inc"
#declare P = pigment { boxed color_map { TwinColors } rotate 30*z scale 3 }
Wall(P)
