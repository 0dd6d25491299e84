#include "sssMaterialUniforms.h"

#include "dipole.h"
#include "material.h"

#include "vtkShaderProgram.h"

#include <cmath>

namespace sss
{

void set_dipole_uniforms(vtkShaderProgram* program, const Dipole& dipole)
{
  float zr[3], zv[3], str[3], factor[3];
  for (int c = 0; c < 3; ++c)
  {
    const DipoleChannel& ch = dipole.channel[c];
    zr[c] = static_cast<float>(ch.z_r);
    zv[c] = static_cast<float>(ch.z_v);
    str[c] = static_cast<float>(ch.s_tr);
    factor[c] = static_cast<float>(ch.alpha_prime / (4.0 * M_PI));
  }
  program->SetUniform3f("zR", zr);
  program->SetUniform3f("zV", zv);
  program->SetUniform3f("sTr", str);
  program->SetUniform3f("rdFactor", factor);
}

void set_eta_uniform(vtkShaderProgram* program, const Material& material)
{
  float eta[3];
  for (int c = 0; c < 3; ++c)
  {
    eta[c] = static_cast<float>(material.eta[c]);
  }
  program->SetUniform3f("eta", eta);
}

}
