// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// vtkCompositeSurfaceDetailMapper: the analytic rectangle of the mapper tests cut into blocks
// (one of them nested), drawn through VTK's composite batching. Every block must show the same
// closed-form picture as the single mapper's (PSNR >= 40 dB), and the composite picture must
// equal the single mapper's pixel for pixel where both draw the same surface.

#include "SurfaceDetailMapperAnalyticScene.h"
#include "vtkCompositeSurfaceDetailMapper.h"
#include "vtkHeightMapToConeMap.h"

#include <vtkCompositePolyDataMapper2.h>
#include <vtkMultiBlockDataSet.h>

namespace
{
// The cells of @a poly whose centre lies left (or right) of x = 0, with every point kept.
vtkSmartPointer<vtkPolyData> Half(vtkPolyData* poly, bool left)
{
  vtkNew<vtkCellArray> cells;
  vtkNew<vtkIdList> ids;
  for (vtkIdType c = 0; c < poly->GetNumberOfCells(); ++c)
  {
    poly->GetCellPoints(c, ids);
    double x = 0.0;
    for (vtkIdType k = 0; k < ids->GetNumberOfIds(); ++k)
    {
      x += poly->GetPoint(ids->GetId(k))[0] / ids->GetNumberOfIds();
    }
    if ((x < 0.0) == left)
    {
      cells->InsertNextCell(ids);
    }
  }
  auto half = vtkSmartPointer<vtkPolyData>::New();
  half->SetPoints(poly->GetPoints());
  half->GetPointData()->ShallowCopy(poly->GetPointData());
  half->SetPolys(cells);
  return half;
}

// The two halves of @a poly as blocks, the right one inside a nested multiblock.
vtkSmartPointer<vtkMultiBlockDataSet> Blocks(vtkPolyData* left, vtkPolyData* right)
{
  vtkNew<vtkMultiBlockDataSet> nested;
  nested->SetBlock(0, right);
  auto blocks = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  blocks->SetBlock(0, left);
  blocks->SetBlock(1, nested);
  return blocks;
}

vtkSmartPointer<vtkCompositeSurfaceDetailMapper> MakeCompositeMapper(vtkDataObject* input)
{
  auto mapper = vtkSmartPointer<vtkCompositeSurfaceDetailMapper>::New();
  mapper->SetInputDataObject(input);
  return mapper;
}

// The largest difference of any channel of any pixel.
int MaxDifference(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b)
{
  int largest = 0;
  for (size_t k = 0; k < a.size() && k < b.size(); ++k)
  {
    largest = std::max(largest, std::abs(static_cast<int>(a[k]) - static_cast<int>(b[k])));
  }
  return a.size() == b.size() ? largest : 255;
}

// The picture of @a configure's technique through the single mapper and through the composite
// one, on the rectangle cut into two blocks.
std::pair<std::vector<unsigned char>, std::vector<unsigned char>> SingleAndComposite(
  const std::function<void(vtkSurfaceDetailMapper*)>& configure, double tilt = 0.0)
{
  auto poly = MakeRectangle(false);
  auto single = MakeMapper(poly);
  configure(single);
  Scene singleScene(single);
  singleScene.Actor->RotateX(tilt);
  auto composite = MakeCompositeMapper(Blocks(Half(poly, true), Half(poly, false)));
  configure(composite->GetDetail());
  Scene compositeScene(composite);
  compositeScene.Actor->RotateX(tilt);
  return { singleScene.Render(), compositeScene.Render() };
}
} // namespace

// Normal mapping on every block: the closed-form picture, and not the flat one.
TEST(vtkCompositeSurfaceDetailMapper, NormalMapOnEveryBlockMatchesAnalyticShading)
{
  auto poly = MakeRectangle(false);
  auto mapper = MakeCompositeMapper(Blocks(Half(poly, true), Half(poly, false)));
  mapper->GetDetail()->SetTechniqueToNormalMapping();
  mapper->GetDetail()->SetNormalMap(MakeNormalMap());
  Scene scene(mapper);
  const auto image = scene.Render();
  EXPECT_GE(PSNR(image, scene.Actor, DetailNormal(false), scene.Mat), 40.0);
  EXPECT_LT(PSNR(image, scene.Actor, FlatNormal(), scene.Mat), 30.0);
}

// A plain vtkPolyData input is one block: the mirrored rectangle reads its handedness there too.
TEST(vtkCompositeSurfaceDetailMapper, PolyDataInputReadsHandedness)
{
  auto mapper = MakeCompositeMapper(MakeRectangle(true));
  mapper->GetDetail()->SetTechniqueToNormalMapping();
  mapper->GetDetail()->SetNormalMap(MakeNormalMap());
  Scene scene(mapper);
  const auto image = scene.Render();
  EXPECT_GE(PSNR(image, scene.Actor, DetailNormal(true), scene.Mat), 40.0);
  EXPECT_LT(PSNR(image, scene.Actor, DetailNormal(false), scene.Mat), 30.0);
}

// Every technique draws the blocks as the single mapper draws the whole surface.
TEST(vtkCompositeSurfaceDetailMapper, EveryTechniqueAsTheSingleMapper)
{
  const std::map<std::string, std::function<void(vtkSurfaceDetailMapper*)>> techniques = {
    { "normal",
      [](vtkSurfaceDetailMapper* m)
      {
        m->SetTechniqueToNormalMapping();
        m->SetNormalMap(MakeNormalMap());
      } },
    { "bump",
      [](vtkSurfaceDetailMapper* m)
      {
        m->SetTechniqueToBumpMapping();
        m->SetHeightMap(MakeHeightMap());
        m->SetBumpScale(Strength);
      } },
    { "bump-tangent-free",
      [](vtkSurfaceDetailMapper* m)
      {
        m->SetTechniqueToBumpMapping();
        m->SetHeightMap(MakeHeightMap());
        m->TangentFreeOn();
      } },
    { "parallax",
      [](vtkSurfaceDetailMapper* m)
      {
        m->SetTechniqueToParallaxMapping();
        m->SetHeightMap(MakeHeightMap());
        m->SetNormalMap(MakeNormalMap());
        m->SetDepthScale(0.1);
      } },
    { "triplanar-normal",
      [](vtkSurfaceDetailMapper* m)
      {
        m->SetTechniqueToNormalMapping();
        m->SetNormalMap(MakeNormalMap());
        m->TriplanarOn();
        m->SetTriplanarScale(0.7);
      } },
    { "relief-shadow-depth",
      [](vtkSurfaceDetailMapper* m)
      {
        m->SetTechniqueToReliefMapping();
        m->SetHeightMap(MakeHeightMap());
        m->SetDepthScale(0.1);
        m->SelfShadowingOn();
        m->DepthCorrectionOn();
      } },
    { "relief-cones-shadow-depth",
      [](vtkSurfaceDetailMapper* m)
      {
        m->SetTechniqueToReliefMapping();
        auto heights = MakeHeightMap();
        m->SetHeightMap(heights);
        vtkNew<vtkHeightMapToConeMap> cones; // Repeat, as the height texture
        cones->SetInputData(heights->GetInput());
        cones->Update();
        vtkNew<vtkTexture> coneTexture;
        coneTexture->SetInputData(cones->GetOutput());
        coneTexture->RepeatOn();
        m->SetConeMap(coneTexture);
        m->SetDepthScale(0.1);
        m->SelfShadowingOn();
        m->DepthCorrectionOn();
      } },
  };
  for (const auto& technique : techniques)
  {
    const auto images = SingleAndComposite(technique.second, 40.0);
    EXPECT_LE(MaxDifference(images.first, images.second), 1) << technique.first;
    // Ten levels is far above the agreement asked for just above: the detail is there.
    const auto plain = SingleAndComposite([](vtkSurfaceDetailMapper*) {}, 40.0);
    EXPECT_GT(MaxDifference(images.second, plain.second), 10)
      << technique.first << ": the technique did not reach the blocks";
  }
}

// Technique Plain is VTK's own composite mapper, pixel for pixel.
TEST(vtkCompositeSurfaceDetailMapper, PlainMatchesVTKCompositeMapper)
{
  auto poly = MakeRectangle(false);
  auto blocks = Blocks(Half(poly, true), Half(poly, false));
  auto mapper = MakeCompositeMapper(blocks);
  mapper->GetDetail()->SetNormalMap(MakeNormalMap());
  Scene scene(mapper);
  vtkNew<vtkCompositePolyDataMapper2> plain;
  plain->SetInputDataObject(blocks);
  Scene reference(plain);
  EXPECT_EQ(scene.Render(), reference.Render());
}

// A block without tangents: one error that names them, and the batch drawn flat, not broken.
TEST(vtkCompositeSurfaceDetailMapper, BlockWithoutTangentsIsReported)
{
  auto poly = MakeRectangle(false);
  auto bare = MakeRectangle(false, /*tangents=*/false);
  auto mapper = MakeCompositeMapper(Blocks(Half(poly, true), Half(bare, false)));
  mapper->GetDetail()->SetTechniqueToNormalMapping();
  mapper->GetDetail()->SetNormalMap(MakeNormalMap());
  vtkNew<ErrorCounter> errors;
  mapper->AddObserver(vtkCommand::ErrorEvent, errors);
  Scene scene(mapper);
  const auto image = scene.Render();
  scene.Render();
  EXPECT_EQ(errors->Errors, 1);
  EXPECT_NE(errors->Last.find("tangents"), std::string::npos) << errors->Last;
  EXPECT_GE(PSNR(image, scene.Actor, FlatNormal(), scene.Mat), 40.0);
}

// One settings object shared by two mappers (ParaView's full and level-of-detail mappers):
// a change shows in both; SetDetail(nullptr) gives a mapper fresh defaults of its own.
TEST(vtkCompositeSurfaceDetailMapper, SharedDetail)
{
  auto poly = MakeRectangle(false);
  auto first = MakeCompositeMapper(poly);
  auto second = MakeCompositeMapper(poly);
  second->SetDetail(first->GetDetail());
  first->GetDetail()->SetTechniqueToNormalMapping();
  first->GetDetail()->SetNormalMap(MakeNormalMap());
  Scene scene(second);
  EXPECT_GE(PSNR(scene.Render(), scene.Actor, DetailNormal(false), scene.Mat), 40.0);

  vtkSurfaceDetailMapper* shared = first->GetDetail();
  second->SetDetail(nullptr);
  ASSERT_NE(second->GetDetail(), nullptr);
  EXPECT_NE(second->GetDetail(), shared);
  EXPECT_EQ(second->GetDetail()->GetTechnique(), vtkSurfaceDetailMapper::Plain);
  EXPECT_EQ(first->GetDetail(), shared);

  std::ostringstream printed;
  first->Print(printed);
  EXPECT_NE(printed.str().find("Technique: NormalMapping"), std::string::npos);
}
