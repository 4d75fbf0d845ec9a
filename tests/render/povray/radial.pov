#include "stage.inc"
#declare P = pigment { radial color_map { TwinColors } frequency 3 rotate -90*x }
Wall(P)
