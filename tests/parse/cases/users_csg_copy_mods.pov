// options: -w
// Copies of a CSG share its children until they change (session 12,
// users_shared_csg). Every modifier given to a copy must reach only the
// copy's children: the plain copy of A first in the dump must keep
// plain children (no texture, interior, flags, photons or transform of
// the later copies), and each later copy must have its own. A nested
// union checks the sharing one level down.
#version 3.7;
#declare A = union {
    sphere { 0, 1 }
    union { box { -0.5, 0.5 } sphere { y, 0.5 } }
}
object { A }
object { A translate x scale 2 }
object { A pigment { rgb 1 } }
object { A texture { pigment { rgb <1, 0, 0> } finish { phong 1 } } }
object { A material { interior { ior 1.5 } } }
object { A interior { ior 1.3 } }
object { A inverse }
object { A no_shadow no_image no_reflection }
object { A double_illuminate hollow }
object { A photons { target 0.5 refraction on reflection off collect off } }
object { A clipped_by { object { A scale 3 } } bounded_by { object { A scale 4 } } }
union { object { A rotate 90 * y } object { A } pigment { rgb 0.5 } }
object { A }
