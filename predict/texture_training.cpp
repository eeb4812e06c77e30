#include "predict/texture_training.hpp"

#include <chrono>
#include <numeric>
#include <random>

#include "core/random_seeds.hpp"
#include "predict/adam.hpp"
#include "predict/chunked_batch.hpp"

namespace haptex::predict {
namespace {

struct Labelled {
  Eigen::MatrixXf x;        // normalised descriptors, one per column
  std::vector<int> label;   // material per column
};

// Descriptors as columns, as they are.
Eigen::MatrixXf stacked(const Descriptors& descriptors, Eigen::Index length) {
  Eigen::MatrixXf x(length, Eigen::Index(descriptors.size()));
  for (std::size_t i = 0; i < descriptors.size(); ++i) x.col(Eigen::Index(i)) = Eigen::Map<const Eigen::VectorXf>(descriptors[i].data(), length);
  return x;
}

// Standardised descriptors, one per column.
Eigen::MatrixXf normalised(const Normalisation& n, const Descriptors& descriptors) {
  Eigen::MatrixXf x = stacked(descriptors, n.descriptor_mean.size()).colwise() - n.descriptor_mean;
  x.array().colwise() /= n.descriptor_scale.array();  // divided, as Predictor::encode_descriptor divides
  return x;
}

Labelled gather(const TrainingData& data, std::size_t set, const Normalisation& n) {
  Labelled out;
  Descriptors all;
  for (std::size_t m = 0; m < data.materials.size(); ++m) {
    const Descriptors& images = data.materials[m].images[set];
    all.insert(all.end(), images.begin(), images.end());
    out.label.insert(out.label.end(), images.size(), int(m));
  }
  out.x = normalised(n, all);
  return out;
}

void descriptor_statistics(const TrainingData& data, Normalisation& n) {
  Descriptors all;
  for (const MaterialData& m : data.materials) all.insert(all.end(), m.images[split::kTrain].begin(), m.images[split::kTrain].end());
  standardisation(stacked(all, Eigen::Index(all.front().size())), n.descriptor_mean, n.descriptor_scale);
}

// Softmax cross-entropy of logits against labels; dLoss/dlogits into d (already / batch size).
double cross_entropy(const Eigen::MatrixXf& logits, const int* label, float scale, Eigen::MatrixXf& d, std::size_t* correct) {
  d.resize(logits.rows(), logits.cols());
  double loss = 0;
  for (Eigen::Index c = 0; c < logits.cols(); ++c) {
    Eigen::Index argmax;
    const float top = logits.col(c).maxCoeff(&argmax);
    const Eigen::VectorXf e = (logits.col(c).array() - top).exp().matrix();
    const float sum = e.sum();
    loss += -std::log(e[label[c]] / sum);
    d.col(c) = e / sum * scale;
    d(label[c], c) -= scale;
    if (correct && argmax == label[c]) ++*correct;
  }
  return loss;
}

struct Evaluation {
  double loss = 0, accuracy = 0;
};

Evaluation evaluate(const Mlp& net, const Labelled& set) {
  MlpTrace trace;
  forward(net, set.x, trace);
  Eigen::MatrixXf d;
  std::size_t correct = 0;
  const double loss = cross_entropy(trace.out.back(), set.label.data(), 0.0f, d, &correct);
  return {loss / double(set.label.size()), double(correct) / double(set.label.size())};
}

// The encoder and its head trained as one network: [descriptor, hidden, latent, materials].
Mlp fit(const Labelled& train, const Labelled& val, const TrainOptions& o, std::size_t materials, const EpochCallback& progress) {
  const int sizes[] = {int(train.x.rows()), o.texture_hidden, o.latent, int(materials)};
  Mlp net = make_mlp(sizes, Activation::relu, Activation::linear, derive_seed(o.seed, 1));
  net.layers[1].activation = Activation::linear;  // the latent
  Adam adam(net, {o.learning_rate});
  MlpGradient total(net);
  std::vector<MlpGradient> slots;
  EarlyStopping stopping(o.texture_patience);
  Mlp best = net;
  std::vector<std::size_t> order(train.label.size());
  std::iota(order.begin(), order.end(), 0);
  const auto start = std::chrono::steady_clock::now();
  for (int epoch = 1; epoch <= o.texture_max_epochs && !stopping.stop(); ++epoch) {
    std::mt19937_64 rng(derive_seed(o.seed, 2, std::uint64_t(epoch)));
    std::shuffle(order.begin(), order.end(), rng);
    double train_loss = 0;
    for (std::size_t b = 0; b < order.size(); b += std::size_t(o.texture_batch)) {
      const std::size_t n = std::min(order.size() - b, std::size_t(o.texture_batch));
      train_loss += chunked_gradient<MlpGradient>(n, slots, total, o.threads, [&](std::size_t begin, std::size_t end, MlpGradient& g) {
        Eigen::MatrixXf x(train.x.rows(), Eigen::Index(end - begin));
        std::vector<int> label;
        for (std::size_t i = begin; i < end; ++i) {
          x.col(Eigen::Index(i - begin)) = train.x.col(Eigen::Index(order[b + i]));
          label.push_back(train.label[order[b + i]]);
        }
        MlpTrace trace;
        forward(net, x, trace);
        Eigen::MatrixXf d;
        const double loss = cross_entropy(trace.out.back(), label.data(), 1.0f / float(n), d, nullptr);
        backward(net, trace, std::move(d), g);
        return loss;
      });
      adam.step(net, total);
    }
    const Evaluation v = evaluate(net, val);
    EpochReport r{"texture", epoch, o.texture_max_epochs, train_loss / double(order.size()), v.loss, v.accuracy, -1,
                  stopping.improved(v.loss), std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()};
    if (r.best) best = net;
    if (stopping.plateau()) adam.set_learning_rate(adam.learning_rate() / 2);
    if (progress) progress(r);
  }
  return best;
}

}  // namespace

Eigen::MatrixXf texture_latents(const Model& model, const Descriptors& descriptors) {
  MlpTrace trace;
  forward(model.texture, normalised(model.normalisation, descriptors), trace);
  return trace.out.back();
}

void train_texture_encoder(const TrainingData& data, const TrainOptions& options, Model& model, const EpochCallback& progress) {
  descriptor_statistics(data, model.normalisation);
  const Labelled train = gather(data, split::kTrain, model.normalisation);
  const Labelled val = gather(data, split::kVal, model.normalisation);
  Mlp net = fit(train, val, options, data.materials.size(), progress);
  const Evaluation on_train = evaluate(net, train), on_val = evaluate(net, val);
  model.classifier.layers = {net.layers.back()};
  net.layers.pop_back();
  model.texture = std::move(net);
  model.material_latents.resize(options.latent, Eigen::Index(data.materials.size()));
  for (std::size_t m = 0; m < data.materials.size(); ++m)
    model.material_latents.col(Eigen::Index(m)) = texture_latents(model, data.materials[m].images[split::kTrain]).rowwise().mean();
  model.metrics["texture"] = {{"train_accuracy", on_train.accuracy}, {"val_accuracy", on_val.accuracy},
                              {"train_cross_entropy", on_train.loss}, {"val_cross_entropy", on_val.loss},
                              {"train_images", train.label.size()}, {"val_images", val.label.size()}};
}

}  // namespace haptex::predict
