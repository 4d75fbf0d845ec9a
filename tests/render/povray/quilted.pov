#include "stage.inc"
#declare P = pigment { quilted color_map { TwinColors } control0 0.3 control1 0.8 scale 1.3 }
Wall(P)
