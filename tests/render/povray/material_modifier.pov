#include "stage.inc"
union {
    box { <-10, -10, 0.3>, <0.3, 10, 1> }
    box { <0.3, -10, 0.3>, <10, 10, 1>
          texture { pigment { color rgb <0.2, 0.7, 0.3> } finish { ambient 0 diffuse 1 } } }
    texture { pigment { checker color rgb <0.9, 0.6, 0.1> color rgb <0.1, 0.3, 0.8> scale 0.7 }
              finish { ambient 0 diffuse 1 } }
}
