"""The include-direction lint names what points up or sideways and lets the rest pass."""
import pathlib
import sys
import unittest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[2] / "scripts"))
import lint_includes  # noqa: E402

P = pathlib.PurePosixPath


class CppIncludes(unittest.TestCase):
    def offence(self, source, target):
        return lint_includes.cpp_offence(P(source), target)

    def test_down_and_within_a_layer_pass(self):
        self.assertIsNone(self.offence("render/FrameRenderer.cpp", "gi/voxel/VoxelizationManager.h"))
        self.assertIsNone(self.offence("scene/Scene.cpp", "core/Colour.h"))
        self.assertIsNone(self.offence("gi/atlas/AtlasGi.cpp", "gi/GiTechnique.h"))
        self.assertIsNone(self.offence("gi/voxel/InjectPass.cpp", "gi/voxel/VoxelTextures.h"))
        self.assertIsNone(self.offence("gl/Shared.h", "common/shared.h"))

    def test_up_is_refused(self):
        self.assertIn("above", self.offence("scene/Scene.h", "render/FrameRenderer.h"))
        self.assertIn("above", self.offence("core/Settings.cpp", "scene/Scene.h"))
        self.assertIn("above", self.offence("gi/GiTechnique.h", "render/ShadowPass.h"))

    def test_siblings_are_refused(self):
        self.assertIn("siblings", self.offence("reference/ImageMetrics.h", "gi/GiTechnique.h"))
        self.assertIn("siblings", self.offence("gi/atlas/Gather.cpp", "gi/voxel/CascadeVolume.h"))
        self.assertIn("technique", self.offence("gi/GiTechnique.h", "gi/voxel/CascadeVolume.h"))

    def test_only_gl_includes_the_glsl_shared_header(self):
        self.assertIn("gl/", self.offence("render/ForwardPass.cpp", "common/shared.h"))


class GlslIncludes(unittest.TestCase):
    def offence(self, source, target):
        return lint_includes.glsl_offence(P(source), target)

    def test_own_folder_and_common_pass(self):
        self.assertIsNone(self.offence("atlas/gather.frag", "atlas_common.glsl"))
        self.assertIsNone(self.offence("atlas/gather.frag", "../common/voxel_cascade.glsl"))
        self.assertIsNone(self.offence("common/frame.glsl", "shared.h"))
        self.assertIsNone(self.offence("voxel/inject.frag", "common/material.glsl"))  # from shaders/

    def test_another_family_is_refused(self):
        self.assertIsNotNone(self.offence("atlas/gather.frag", "../voxel/voxel_lock.glsl"))
        self.assertIsNotNone(self.offence("render/forward.frag", "voxel/voxel_lock.glsl"))
        self.assertIsNotNone(self.offence("common/material.glsl", "../voxel/voxel_lock.glsl"))

    def test_the_tree_as_committed_is_clean(self):
        failures = lint_includes.check("src", {".h", ".cpp"}, lint_includes.cpp_offence)
        failures += lint_includes.check("shaders", {".glsl", ".vert", ".frag", ".comp"},
                                        lint_includes.glsl_offence)
        self.assertEqual(failures, [])


if __name__ == "__main__":
    unittest.main()
