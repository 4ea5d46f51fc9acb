// The DQN agent's torch modules (seed §3.3.4, §3.3.5): the interpretive networks for visual,
// episode and audio arrays and the Q network over their features. Included by dqn_agent.cpp
// only, so torch stays out of every other file.
#pragma once
#include <torch/torch.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "rl/agents/dqn_agent.h"

namespace psxrl::agents {

// One observation array's place in a state vector (features() order).
struct Slice {
  rl::Space space;
  std::int64_t offset = 0, size = 0;
};

// Seed Fig. 3.15: the frame's planes scaled from bytes to [0, 1], two convolutions with PReLU,
// flattened (32 x 6 x 6 = 1152 features for an 80x60 frame).
struct VisualNetImpl : torch::nn::Module {
  VisualNetImpl(std::int64_t planes, std::int64_t height, std::int64_t width)
      : planes(planes), height(height), width(width) {
    using torch::nn::Conv2dOptions;
    conv1 = register_module("conv1", torch::nn::Conv2d(Conv2dOptions(planes, kConv1Filters, kConv1Kernel).stride(kConv1Stride)));
    prelu1 = register_module("prelu1", torch::nn::PReLU());
    conv2 = register_module("conv2", torch::nn::Conv2d(Conv2dOptions(kConv1Filters, kConv2Filters, kConv2Kernel)
                                                           .stride({kConv2StrideY, kConv2StrideX})));
    prelu2 = register_module("prelu2", torch::nn::PReLU());
  }
  torch::Tensor forward(torch::Tensor x) {
    x = x.reshape({-1, planes, height, width}) / 255.0f;
    return prelu2->forward(conv2->forward(prelu1->forward(conv1->forward(x)))).flatten(1);
  }
  std::int64_t planes, height, width;
  torch::nn::Conv2d conv1{nullptr}, conv2{nullptr};
  torch::nn::PReLU prelu1{nullptr}, prelu2{nullptr};
};
TORCH_MODULE(VisualNet);

// A small fully connected interpreter: inputs -> hidden -> features, PReLU after each (the seed's
// episode network is 3 -> hidden -> 6; the audio one is ours).
struct FeatureNetImpl : torch::nn::Module {
  FeatureNetImpl(std::int64_t inputs, std::int64_t hidden, std::int64_t features) {
    fc1 = register_module("fc1", torch::nn::Linear(inputs, hidden));
    prelu1 = register_module("prelu1", torch::nn::PReLU());
    fc2 = register_module("fc2", torch::nn::Linear(hidden, features));
    prelu2 = register_module("prelu2", torch::nn::PReLU());
  }
  torch::Tensor forward(torch::Tensor x) {
    return prelu2->forward(fc2->forward(prelu1->forward(fc1->forward(x))));
  }
  torch::nn::Linear fc1{nullptr}, fc2{nullptr};
  torch::nn::PReLU prelu1{nullptr}, prelu2{nullptr};
};
TORCH_MODULE(FeatureNet);

// The Q network: optional interpretive networks, one per observation array, whose features are
// concatenated, then the seed's head: 4 hidden fully connected PReLU layers and `actions`
// outputs with tanh (or linear). Without interpreters the head reads the state as it is: the
// agent-local network of 5 Linear layers with 11 inputs and 4 outputs.
struct QNetImpl : torch::nn::Module {
  static constexpr int kHiddenLayers = 4;
  QNetImpl(const std::vector<Slice>& slices, bool interpret, int hidden, int actions, bool linear_output)
      : slices(slices), interpret(interpret), linear_output(linear_output) {
    std::int64_t in = 0;
    for (const Slice& s : slices) in += interpret ? add_interpreter(s) : s.size;
    head_inputs = in;
    for (int i = 0; i < kHiddenLayers; ++i) {
      fc.push_back(register_module("fc" + std::to_string(i), torch::nn::Linear(in, hidden)));
      act.push_back(register_module("prelu" + std::to_string(i), torch::nn::PReLU()));
      in = hidden;
    }
    out = register_module("out", torch::nn::Linear(hidden, actions));
  }

  torch::Tensor forward(torch::Tensor x) {
    if (interpret) {
      std::vector<torch::Tensor> features;
      for (size_t i = 0; i < slices.size(); ++i) {
        torch::Tensor part = x.narrow(1, slices[i].offset, slices[i].size);
        const std::string& name = slices[i].space.name;
        features.push_back(name == "visual" ? visual->forward(part)
                           : name == "episode" ? episode->forward(part)
                                               : audio->forward(part));
      }
      x = torch::cat(features, 1);
    }
    for (size_t i = 0; i < fc.size(); ++i) x = act[i]->forward(fc[i]->forward(x));
    x = out->forward(x);
    return linear_output ? x : torch::tanh(x);
  }

  std::vector<Slice> slices;
  bool interpret, linear_output;
  std::int64_t head_inputs = 0;
  VisualNet visual{nullptr};
  FeatureNet episode{nullptr}, audio{nullptr};
  std::vector<torch::nn::Linear> fc;
  std::vector<torch::nn::PReLU> act;
  torch::nn::Linear out{nullptr};

 private:
  // Registers the array's interpreter; returns how many features it gives the head.
  std::int64_t add_interpreter(const Slice& s) {
    const auto& shape = s.space.shape;
    if (s.space.name == "visual" && shape.size() == 3) {
      std::int64_t n = visual_features(shape[1], shape[2]);
      if (n == 0)
        throw std::invalid_argument("the visual network needs frames of at least 20x20 pixels, not " +
                                    std::to_string(shape[2]) + "x" + std::to_string(shape[1]));
      visual = register_module("visual", VisualNet(shape[0], shape[1], shape[2]));
      return n;
    }
    if (s.space.name == "episode") {
      episode = register_module("episode", FeatureNet(s.size, kEpisodeHidden, kEpisodeFeatures));
      return kEpisodeFeatures;
    }
    if (s.space.name == "audio") {
      audio = register_module("audio", FeatureNet(s.size, kAudioHidden, kAudioFeatures));
      return kAudioFeatures;
    }
    throw std::invalid_argument("the multimodal network has no interpretive network for the '" + s.space.name +
                                "' array");
  }
};
TORCH_MODULE(QNet);

}  // namespace psxrl::agents
