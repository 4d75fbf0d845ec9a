#include "stage.inc"
#declare P = pigment { checker color rgb 0.3 color rgb 0.5 scale 1 }
Wall(P)
#declare Red = texture { pigment { color rgb <0.9, 0.3, 0.2> } finish { ambient 0 diffuse 1 } }
#declare Green = texture { pigment { color rgb <0.3, 0.9, 0.3> } finish { ambient 0 diffuse 1 } }
#declare Blue = texture { pigment { color rgb <0.3, 0.4, 0.95> } finish { ambient 0 diffuse 1 } }
#macro Cube(T)
mesh2 {
    vertex_vectors { 8, <-1, -1, -1>, <1, -1, -1>, <1, 1, -1>, <-1, 1, -1>,
                        <-1, -1, 1>, <1, -1, 1>, <1, 1, 1>, <-1, 1, 1> }
    face_indices { 12, <0, 2, 1>, <0, 3, 2>, <4, 5, 6>, <4, 6, 7>, <0, 1, 5>, <0, 5, 4>,
                       <3, 6, 2>, <3, 7, 6>, <0, 4, 7>, <0, 7, 3>, <1, 2, 6>, <1, 6, 5> }
    inside_vector <0.1, 0.2, 1>
    texture { T }
}
#end
difference { object { Cube(Red) } sphere { <0, 0, -1>, 0.8 texture { Blue } }
             scale 0.8 rotate <-20, 30, 0> translate <-1.4, 1, -1> }
intersection { object { Cube(Green) } sphere { <0, 0, 0>, 1.3 texture { Green } }
               scale 0.8 rotate <25, -20, 0> translate <1.4, 1, -1> }
object { Cube(Blue) clipped_by { sphere { <0, 0, 0>, 1.25 } }
         scale 0.8 rotate <-30, 40, 0> translate <0, -1.4, -1> }
