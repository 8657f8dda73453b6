// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// The study's plots: image error against frame time for one scene, drawn with VTK's own
// charts (vtkChartXY in an offscreen vtkContextView) and written as a PNG.

#include "SurfaceDetailStudy.h"

#include <vtkAxis.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextScene.h>
#include <vtkContextView.h>
#include <vtkDoubleArray.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPen.h>
#include <vtkPlot.h>
#include <vtkPlotPoints.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTable.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <iterator>
#include <map>

namespace SurfaceDetailStudy
{
namespace
{
vtkSmartPointer<vtkTable> MakeTable(const std::string& name)
{
  auto table = vtkSmartPointer<vtkTable>::New();
  vtkNew<vtkDoubleArray> x, y;
  x->SetName("frame time (ms)");
  y->SetName(name.c_str());
  table->AddColumn(x);
  table->AddColumn(y);
  return table;
}

void Append(vtkTable* table, double x, double y)
{
  const vtkIdType row = table->InsertNextBlankRow();
  table->SetValue(row, 0, x);
  table->SetValue(row, 1, y);
}

// Distinct colours (8-bit RGB) and markers per family, in the order families first appear.
const unsigned char Palette[][3] = { { 90, 90, 90 }, { 31, 119, 180 }, { 23, 190, 207 },
  { 44, 160, 44 }, { 148, 103, 189 }, { 255, 127, 14 }, { 188, 189, 34 }, { 140, 86, 75 },
  { 214, 39, 40 }, { 227, 119, 194 }, { 110, 0, 0 }, { 150, 40, 140 } };
const int Markers[] = { vtkPlotPoints::CROSS, vtkPlotPoints::CIRCLE, vtkPlotPoints::SQUARE,
  vtkPlotPoints::DIAMOND, vtkPlotPoints::PLUS, vtkPlotPoints::CIRCLE, vtkPlotPoints::SQUARE,
  vtkPlotPoints::DIAMOND, vtkPlotPoints::CIRCLE, vtkPlotPoints::SQUARE, vtkPlotPoints::DIAMOND,
  vtkPlotPoints::DIAMOND };
} // namespace

void PlotScene(const std::string& title, const std::vector<const Row*>& rows,
  double convergenceRMSE, const std::string& pngPath)
{
  vtkNew<vtkContextView> view;
  view->GetRenderWindow()->SetOffScreenRendering(1);
  view->GetRenderWindow()->SetMultiSamples(0);
  view->GetRenderWindow()->SetSize(1000, 700);
  view->GetRenderer()->SetBackground(1, 1, 1);
  vtkNew<vtkChartXY> chart;
  view->GetScene()->AddItem(chart);
  chart->SetTitle(title + ": image error against frame time (front: black line)");
  chart->GetTitleProperties()->SetFontSize(18);
  chart->SetShowLegend(true);
  chart->GetLegend()->SetHorizontalAlignment(vtkChartLegend::RIGHT);
  chart->GetLegend()->SetVerticalAlignment(vtkChartLegend::TOP);
  chart->GetLegend()->GetLabelProperties()->SetFontSize(13);

  std::vector<std::string> order;
  std::map<std::string, vtkSmartPointer<vtkTable>> families;
  double xMin = 1e300, xMax = 0, yMax = 0;
  std::vector<const Row*> front;
  for (const Row* r : rows)
  {
    if (r->Truth)
    {
      continue;
    }
    if (!families.count(r->Family))
    {
      families[r->Family] = MakeTable(r->Family);
      order.push_back(r->Family);
    }
    Append(families[r->Family], r->FrameMs, r->RMSE);
    xMin = std::min(xMin, r->FrameMs);
    xMax = std::max(xMax, r->FrameMs);
    yMax = std::max(yMax, r->RMSE);
    if (r->OnFront)
    {
      front.push_back(r);
    }
  }
  std::sort(
    front.begin(), front.end(), [](const Row* a, const Row* b) { return a->FrameMs < b->FrameMs; });
  // The front as a staircase: each point's error holds until a faster-to-reach better one.
  vtkSmartPointer<vtkTable> line = MakeTable("Pareto front");
  for (size_t k = 0; k < front.size(); ++k)
  {
    Append(line, front[k]->FrameMs, front[k]->RMSE);
    if (k + 1 < front.size())
    {
      Append(line, front[k + 1]->FrameMs, front[k]->RMSE);
    }
  }
  vtkPlot* frontPlot = chart->AddPlot(vtkChart::LINE);
  frontPlot->SetInputData(line, 0, 1);
  frontPlot->SetColor(0, 0, 0, 255);
  frontPlot->SetWidth(1.5);
  // The truth's own convergence: errors below it cannot be told apart.
  vtkSmartPointer<vtkTable> floor = MakeTable("truth vs 2x truth (RMSE)");
  Append(floor, 0.8 * xMin, convergenceRMSE);
  Append(floor, 1.25 * xMax, convergenceRMSE);
  vtkPlot* floorPlot = chart->AddPlot(vtkChart::LINE);
  floorPlot->SetInputData(floor, 0, 1);
  floorPlot->SetColor(150, 150, 150, 255);
  floorPlot->GetPen()->SetLineType(vtkPen::DASH_LINE);
  for (size_t k = 0; k < order.size(); ++k)
  {
    auto* plot = vtkPlotPoints::SafeDownCast(chart->AddPlot(vtkChart::POINTS));
    plot->SetInputData(families[order[k]], 0, 1);
    const unsigned char* c = Palette[k % std::size(Palette)];
    plot->SetColor(c[0], c[1], c[2], 255);
    plot->SetMarkerStyle(Markers[k % std::size(Markers)]);
    plot->SetMarkerSize(11);
    plot->SetWidth(2.0);
  }
  vtkAxis* x = chart->GetAxis(vtkAxis::BOTTOM);
  x->SetTitle("median frame time (ms, log scale), Mesa llvmpipe");
  x->SetLogScale(true);
  x->SetBehavior(vtkAxis::FIXED);
  x->SetRange(0.8 * xMin, 1.25 * xMax);
  vtkAxis* y = chart->GetAxis(vtkAxis::LEFT);
  y->SetTitle("RMSE against the displaced-mesh truth (8-bit levels, object pixels)");
  y->SetBehavior(vtkAxis::FIXED);
  y->SetRange(0.0, 1.05 * yMax);
  for (vtkAxis* axis : { x, y })
  {
    axis->GetTitleProperties()->SetFontSize(15);
    axis->GetLabelProperties()->SetFontSize(13);
  }

  view->GetRenderWindow()->Render();
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(view->GetRenderWindow());
  grab->SetInputBufferTypeToRGB();
  grab->ReadFrontBufferOff();
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  writer->SetFileName(pngPath.c_str());
  writer->Write();
}
} // namespace SurfaceDetailStudy
