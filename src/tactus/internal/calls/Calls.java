package tactus.internal.calls;

import tactus.internal.model.Check;
import tactus.internal.realtime.ModelLock;
import tactus.internal.ModelCore;

/**
 * The second half of a facade call of {@code PhysicalModel}: the facade checks what it can without the model and
 * documents the call; the call classes enter the model ({@link ModelLock}), turn names and indices into ids (with
 * the paper's leniency for indices past the end) and hand the work to the room that does it. Not API.
 */
public abstract class Calls {
    protected final ModelCore core;
    protected final ModelLock gate;

    protected Calls(ModelCore core, ModelLock gate) {
        this.core = core;
        this.gate = gate;
    }

    protected final void enter() {
        gate.enter();
    }

    protected final void enterChange() {
        gate.enterChange();
    }

    protected final void exit() {
        gate.exit();
    }

    protected final <T> T structural(java.util.function.Supplier<T> body) {
        return gate.structural(body);
    }

    protected final void structuralDo(Runnable body) {
        gate.structuralDo(body);
    }

    protected int paperMassAt(String op, int i, String skipped) {
        int n = core.dir.mats.size();
        if (i >= n && !core.lenient.strict()) {
            core.lenient.forgiveIndex(op, i, "mass index out of range"
                    + (n == 0 ? " (the model has none)" : " 0.." + (n - 1)), skipped);
            return -1;
        }
        return core.dir.massAt(op, i);
    }

    protected int paperLinkAt(String op, int i, String skipped) {
        int n = core.dir.links.size();
        if (i >= n && !core.lenient.strict()) {
            core.lenient.forgiveIndex(op, i, "interaction index out of range"
                    + (n == 0 ? " (the model has none)" : " 0.." + (n - 1)), skipped);
            return -1;
        }
        return core.dir.linkAt(op, i);
    }

    /**
     * Runs {@code body} inside the model as a read enters (for the facade's own bookkeeping that the stepping calls
     * see, its parameter controllers).
     */
    public final <T> T read(java.util.function.Supplier<T> body) {
        enter();
        try {
            return body.get();
        } finally {
            exit();
        }
    }

    protected final boolean hasSubset(String subset, boolean mats) {
        enter();
        try {
            return mats ? core.subsets.isMatSubset(subset) : core.subsets.isLinkSubset(subset);
        } finally {
            exit();
        }
    }

    protected static void checkForce(String op, String element, double fx, double fy, double fz) {
        Check.finite(op, element, "fx", fx);
        Check.finite(op, element, "fy", fy);
        Check.finite(op, element, "fz", fz);
    }

    public boolean matExists(String name) {
        enter();
        try {
            return core.dir.mats.id(name) >= 0;
        } finally {
            exit();
        }
    }

    public boolean linkExists(String name) {
        enter();
        try {
            return core.dir.links.id(name) >= 0;
        } finally {
            exit();
        }
    }
}
