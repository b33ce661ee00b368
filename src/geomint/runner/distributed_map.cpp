#include "geomint/runner/distributed_map.hpp"

#include "geomint/core/numerical_failure.hpp"
#include "geomint/io/atomic_file.hpp"
#include "geomint/runner/experiment.hpp"
#include "geomint/scene/scene.hpp"

namespace geomint {

void throw_everywhere(int owner, std::exception_ptr error) {
  enum Kind { other, scene, numerical, output, interrupted };
  std::string message = "(no message)";
  double kind = other;
  if (mpi::rank() == owner) try {
      std::rethrow_exception(error);
    } catch (const SceneError& e) {
      kind = scene, message = e.what();
    } catch (const NumericalFailure& e) {
      kind = numerical, message = e.what();
    } catch (const OutputError& e) {
      kind = output, message = e.what();
    } catch (const Interrupted& e) {
      kind = interrupted, message = e.what();
    } catch (const std::exception& e) {
      message = e.what();
    } catch (...) {
    }
  std::vector<double> k{kind};
  mpi::broadcast(k, owner), mpi::broadcast(message, owner);
  if (mpi::rank() == owner) std::rethrow_exception(error);
  switch (static_cast<int>(k[0])) {
    case scene: throw SceneError(message);
    case numerical: throw NumericalFailure(message);
    case output: throw OutputError(message);
    case interrupted: throw Interrupted(message);
    default: throw std::runtime_error(message);
  }
}

}  // namespace geomint
