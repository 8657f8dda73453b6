// SPDX-FileCopyrightText: Copyright (c) 2026 the SurfaceDetail developers
// SPDX-License-Identifier: BSD-3-Clause
// Helpers shared by the parametric-surface GoogleTest programs.
#ifndef ParametricSurfaceTestHelpers_h
#define ParametricSurfaceTestHelpers_h

#include <vtkAlgorithm.h>
#include <vtkCommand.h>
#include <vtkExecutive.h>
#include <vtkObject.h>

#include <string>

/// Records ErrorEvent and WarningEvent messages of the objects it observes, so that tests
/// can assert that an error was reported (and VTK prints nothing to the test log). For an
/// algorithm it also swallows its executive's "returned failure" error, counted apart.
class ParametricErrorObserver : public vtkCommand
{
public:
  static ParametricErrorObserver* New() { return new ParametricErrorObserver; }
  void Execute(vtkObject* caller, unsigned long event, void* callData) override
  {
    if (vtkExecutive::SafeDownCast(caller))
    {
      ++this->ExecutiveErrorCount;
      return;
    }
    const std::string text = callData ? static_cast<const char*>(callData) : "";
    if (event == vtkCommand::ErrorEvent)
    {
      this->Errors += text;
      ++this->ErrorCount;
    }
    else if (event == vtkCommand::WarningEvent)
    {
      this->Warnings += text;
      ++this->WarningCount;
    }
  }
  void Observe(vtkObject* object)
  {
    object->AddObserver(vtkCommand::ErrorEvent, this);
    object->AddObserver(vtkCommand::WarningEvent, this);
    if (auto* algorithm = vtkAlgorithm::SafeDownCast(object))
    {
      algorithm->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, this);
    }
  }
  void Clear()
  {
    this->Errors.clear();
    this->Warnings.clear();
    this->ErrorCount = 0;
    this->WarningCount = 0;
    this->ExecutiveErrorCount = 0;
  }
  std::string Errors;
  std::string Warnings;
  int ErrorCount = 0;
  int WarningCount = 0;
  int ExecutiveErrorCount = 0;
};

#endif
