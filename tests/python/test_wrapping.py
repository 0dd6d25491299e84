"""The wrapped classes work with vtkmodules objects in both directions (run by CTest with the
build tree's `sss` on PYTHONPATH and no LD_LIBRARY_PATH)."""
import unittest

from vtkmodules.vtkCommonDataModel import vtkPolyData
from vtkmodules.vtkRenderingCore import vtkActor, vtkRenderer, vtkRenderPass, vtkRenderWindow

import sss


class Wrapping(unittest.TestCase):
    def test_vtkmodules_objects_pass_in_and_come_back_unchanged(self):
        actor = vtkActor()
        mapper = sss.vtkSurfelMapper()
        mapper.SetInputData(vtkPolyData())
        actor.SetMapper(mapper)
        self.assertIs(actor.GetMapper(), mapper)

        material = sss.vtkTranslucentMaterial()
        self.assertTrue(material.SetPreset("ketchup"))
        material.ApplyTo(actor)
        self.assertIs(sss.vtkTranslucentMaterial.GetFrom(actor), material)

        subsurface = sss.vtkSubsurfacePass()
        self.assertIsInstance(subsurface, vtkRenderPass)
        renderer = vtkRenderer()
        renderer.SetPass(subsurface)
        self.assertIs(renderer.GetPass(), subsurface)

        window = sss.vtkEGLSurfacelessRenderWindow()
        self.assertIsInstance(window, vtkRenderWindow)
        window.AddRenderer(renderer)
        self.assertIs(window.GetRenderers().GetFirstRenderer(), renderer)

    def test_classes_live_in_their_modules(self):
        self.assertEqual(sss.vtkSurfelMapper.__module__, "sss.sssTranslucency")
        self.assertEqual(sss.vtkEGLSurfacelessRenderWindow.__module__, "sss.sssHeadless")

    def test_quality_presets_by_name(self):
        subsurface = sss.vtkSubsurfacePass()
        self.assertEqual(subsurface.GetQualityPresetAsString(), "balanced")
        self.assertTrue(subsurface.SetQualityPreset("accurate"))
        self.assertEqual(subsurface.GetCellSamples(), 128)
        self.assertAlmostEqual(subsurface.GetOpeningAngle(), 0.3)
        self.assertFalse(subsurface.SetQualityPreset("fastest"))
        self.assertEqual(subsurface.GetQualityPresetAsString(), "accurate")
        subsurface.SetCellSamples(32)
        self.assertEqual(subsurface.GetQualityPresetAsString(), "")

    def test_refinement_is_reachable_and_off_by_default(self):
        subsurface = sss.vtkSubsurfacePass()
        self.assertFalse(subsurface.GetRefinement())
        subsurface.RefinementOn()
        subsurface.SetRefinementRestSeconds(0.5)
        subsurface.SetRefinementFrameSeconds(0.2)
        self.assertTrue(subsurface.GetRefinement())
        self.assertAlmostEqual(subsurface.GetRefinementRestSeconds(), 0.5)
        self.assertAlmostEqual(subsurface.GetRefinementFrameSeconds(), 0.2)
        self.assertFalse(subsurface.GetRefinementPending())
        self.assertEqual(subsurface.GetRefinedShare(), 1.0)
        self.assertLess(subsurface.GetLastPreviewError(), 0.0)


if __name__ == "__main__":
    unittest.main()
