#pragma once

#include "itk_image_io.hpp"

#include <algorithm>
#include <itkThresholdSegmentationLevelSetImageFilter.h>

namespace steerseg::itkbench {

// ITK's threshold level-set filter, counting the PDE time it has evolved (the sum of its time
// steps, which ITK does not keep) and optionally stopping at a given time. The last step is
// shortened to land on the time exactly, so that two solvers can be compared at the same point
// of the PDE. ApplyUpdate and Halt are the FiniteDifferenceImageFilter hooks called once per
// iteration by its GenerateData loop.
class TimedThresholdLevelSetFilter
    : public itk::ThresholdSegmentationLevelSetImageFilter<FloatImage, FloatImage, float> {
  public:
    using Self = TimedThresholdLevelSetFilter;
    using Superclass = itk::ThresholdSegmentationLevelSetImageFilter<FloatImage, FloatImage, float>;
    using Pointer = itk::SmartPointer<Self>;
    using ConstPointer = itk::SmartPointer<const Self>;

    // What itkNewMacro expands to, written out: ITK 5.2's macros leave a stray ';' that
    // -Wpedantic rejects. An ITK object starts with one reference, which the Pointer takes over.
    static Pointer New() {
        Pointer object = new Self;
        object->UnRegister();
        return object;
    }
    [[nodiscard]] const char* GetNameOfClass() const override {
        return "TimedThresholdLevelSetFilter";
    }

    // 0 (the default) means no time limit.
    void SetTimeLimit(double t) { m_TimeLimit = t; }
    [[nodiscard]] double GetEvolvedTime() const { return m_EvolvedTime; }

  protected:
    TimedThresholdLevelSetFilter() = default;

    void ApplyUpdate(const TimeStepType& dt) override {
        TimeStepType step = dt;
        if (m_TimeLimit > 0.0) {
            step = std::min(step, m_TimeLimit - m_EvolvedTime);
        }
        Superclass::ApplyUpdate(step);
        m_EvolvedTime += step;
    }

    bool Halt() override {
        if (m_TimeLimit > 0.0 && m_EvolvedTime >= m_TimeLimit * (1.0 - 1e-12)) {
            return true;
        }
        return Superclass::Halt();
    }

  private:
    double m_TimeLimit = 0.0;
    double m_EvolvedTime = 0.0;
};

} // namespace steerseg::itkbench
