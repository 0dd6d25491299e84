// The material's uniforms of dipole.glsl, packed in one place for every program that uses
// them: per channel the dipole's z_r, z_v, s_tr and alpha' / 4 pi (eq. 5-13), and eta.
#ifndef sssMaterialUniforms_h
#define sssMaterialUniforms_h

class vtkShaderProgram;

namespace sss
{

struct Dipole;
struct Material;

// zR, zV, sTr and rdFactor.
void set_dipole_uniforms(vtkShaderProgram* program, const Dipole& dipole);
// eta, for Ft (eq. 14-15).
void set_eta_uniform(vtkShaderProgram* program, const Material& material);

}

#endif
