#include "stage.inc"
#declare P = pigment { checker color rgb 0.3 color rgb 0.5 scale 1 }
Wall(P)
#declare Red = texture { pigment { color rgb <0.9, 0.3, 0.2> } finish { ambient 0 diffuse 1 } }
#declare Blue = texture { pigment { color rgb <0.3, 0.4, 0.95> } finish { ambient 0 diffuse 1 } }
mesh2 {
    vertex_vectors { 5, <-1, 0, -1>, <1, 0, -1>, <1, 0, 1>, <-1, 0, 1>, <0, 1.4, 0> }
    face_indices { 6, <0, 1, 4>, <1, 2, 4>, <2, 3, 4>, <3, 0, 4>, <0, 2, 1>, <0, 3, 2> }
    texture { Red } rotate <-25, 30, 0> translate <-1.3, 0.4, -1>
}
mesh2 {
    vertex_vectors { 6, <1, 0, 0>, <-1, 0, 0>, <0, 1, 0>, <0, -1, 0>, <0, 0, 1>, <0, 0, -1> }
    normal_vectors { 6, <1, 0, 0>, <-2, 0, 0>, <0, 1, 0>, <0, -1, 0>, <0, 0, 1>, <0, 0, -1> }
    face_indices { 8, <0, 2, 4>, <2, 1, 4>, <1, 3, 4>, <3, 0, 4>, <2, 0, 5>, <1, 2, 5>, <3, 1, 5>, <0, 3, 5> }
    texture { Blue } rotate <20, 35, 10> translate <1.3, 0, -1>
}
