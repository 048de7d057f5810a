package tactus.io;

import java.util.concurrent.locks.Lock;
import java.util.function.Supplier;
import tactus.PhysicalModel;

/** Runs a sequence of model calls atomically, holding the model's lock whatever form {@code getLock()} returns. */
final class ModelLocks {
    private ModelLocks() {
    }

    static <T> T locked(PhysicalModel model, Supplier<T> body) {
        Object lock = model.getLock();
        if (lock instanceof Lock) {
            Lock l = (Lock) lock;
            l.lock();
            try {
                return body.get();
            } finally {
                l.unlock();
            }
        }
        synchronized (lock) {
            return body.get();
        }
    }
}
