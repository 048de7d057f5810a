package tactus.bench;

import java.lang.invoke.MethodHandle;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.MethodType;
import java.lang.reflect.Field;
import java.lang.reflect.Method;
import java.util.Locale;
import tactus.PhysicalModel;
import tactus.engine.Engine;
import tactus.engine.LinkKind;
import tactus.engine.StepPlan;

/**
 * Where a step's time goes: runs the compiled plan's kernels one by one, in the plan's order (so the physics is
 * the same as a normal step), timing each with System.nanoTime, and also times whole normal steps
 * (the package-private {@code StepPlan.step()}) and the divergence guard's scan ({@link Engine#checkNow()}, amortised over its
 * interval of 64 steps) in alternating blocks.
 *
 * <p>The kernels are package-private engine internals, reached by reflection; this is a diagnostic only, and it
 * reports nothing (rather than failing the benchmark) if the engine's internals change shape. Each kernel
 * timing includes one nanoTime call (about 20 ns), which matters only for kernels of a few elements.
 *
 * <p>Every figure is the median over blocks of 64 steps of the time per step, so a block in which the thread was
 * descheduled does not move it.
 *
 * <p>Output: entries {@code name~elements~nsPerStep} joined by {@code |}; the pseudo-entries {@code step} (a
 * whole normal step) and {@code guard} (the divergence scan per step) come first.
 */
final class KernelProfiler {
    private static final int BLOCK = 64;

    private KernelProfiler() {
    }

    static String profile(Object model, double seconds) throws ReflectiveOperationException {
        Engine engine;
        if (model instanceof Engine) {
            engine = (Engine) model;
        } else if (model instanceof PhysicalModel) {
            Field f = PhysicalModel.class.getDeclaredField("core");
            f.setAccessible(true);
            Object core = f.get(model);
            engine = (Engine) core.getClass().getField("engine").get(core); // declared by the model's shared base
        } else {
            return "";
        }
        StepPlan plan = engine.plan();
        Field kf = StepPlan.class.getDeclaredField("kernels");
        kf.setAccessible(true);
        Object[] ks = ((Object[]) kf.get(plan)).clone();
        Method run = Class.forName("tactus.engine.Kernel").getDeclaredMethod("run");
        run.setAccessible(true);
        MethodHandle mh = MethodHandles.lookup().unreflect(run).asType(MethodType.methodType(void.class, Object.class));
        Method stepMethod = StepPlan.class.getDeclaredMethod("step");
        stepMethod.setAccessible(true);
        MethodHandle step = MethodHandles.lookup().unreflect(stepMethod);
        int nk = ks.length;
        long[] rebuilds0 = new long[nk];
        for (int i = 0; i < nk; i++) {
            rebuilds0[i] = rebuilds(ks[i]);
        }
        // per block of 64 steps: each kernel's time, the whole-step time, the guard's time
        java.util.List<long[]> blocks = new java.util.ArrayList<>();
        long end = System.nanoTime() + (long) (seconds * 1e9);
        try {
            while (System.nanoTime() < end || blocks.size() < 5) {
                long[] b = new long[nk + 2];
                for (int s = 0; s < BLOCK; s++) {
                    for (int i = 0; i < nk; i++) {
                        long t0 = System.nanoTime();
                        mh.invokeExact(ks[i]);
                        b[i] += System.nanoTime() - t0;
                    }
                }
                long t0 = System.nanoTime();
                for (int s = 0; s < BLOCK; s++) {
                    step.invokeExact(plan);
                }
                long t1 = System.nanoTime();
                engine.checkNow();
                long t2 = System.nanoTime();
                b[nk] = t1 - t0;
                b[nk + 1] = t2 - t1;
                blocks.add(b);
            }
        } catch (Throwable t) {
            throw new IllegalStateException("kernel call failed", t);
        }
        // the median over blocks: a block in which the thread was descheduled does not move it
        double[] med = new double[nk + 2];
        double[] v = new double[blocks.size()];
        for (int i = 0; i < nk + 2; i++) {
            for (int j = 0; j < v.length; j++) {
                v[j] = blocks.get(j)[i];
            }
            med[i] = Harness.median(v) / BLOCK;
        }
        StringBuilder sb = new StringBuilder();
        sb.append(String.format(Locale.ROOT, "step~0~%.1f", med[nk]));
        sb.append(String.format(Locale.ROOT, "|guard~0~%.1f", med[nk + 1] * BLOCK / engine.guard().interval()));
        long kernelSteps = (long) blocks.size() * BLOCK;
        for (int i = 0; i < nk; i++) {
            String[] d = describe(ks[i]);
            if (rebuilds0[i] >= 0) {
                // 2 steps per block-step: the per-kernel pass and the whole-step pass both step the kernel
                double perStep = (rebuilds(ks[i]) - rebuilds0[i]) / (2.0 * kernelSteps);
                d[0] = d[0] + String.format(Locale.ROOT, ", %.3g list rebuilds per step", perStep);
            }
            sb.append('|').append(d[0]).append('~').append(d[1]).append('~')
                    .append(String.format(Locale.ROOT, "%.1f", med[i]));
        }
        return sb.toString();
    }

    /** @return {name, element count} of a kernel, read from its fields; the count is -1 when unknown. */
    private static String[] describe(Object k) {
        String name = k.getClass().getSimpleName();
        long count = -1;
        try {
            Object run = field(k, "r");
            Object batch = field(k, "b");
            if (run != null) {
                int s = (Integer) field(run, "s");
                int e = (Integer) field(run, "e");
                int o = (Integer) field(run, "o");
                name = "StencilKernel(o=" + o + ")";
                count = e - s;
                Object masses = field(k, "masses");
                if (masses != null) {
                    // a run that moves its own masses: slots [s, e + o)
                    name = name + " + its masses (" + masses.getClass().getSimpleName() + ")";
                    count += e + o - s;
                }
            } else if (batch != null) {
                LinkKind kind = (LinkKind) field(batch, "kind");
                int n = (Integer) field(batch, "n");
                Object irr = field(batch, "nIrregular");
                boolean stencilKind = kind == LinkKind.SPRING3D || kind == LinkKind.DAMPER3D
                        || kind == LinkKind.SPRING_DAMPER3D;
                count = stencilKind && irr != null ? (Integer) irr : n;
                name = kind.label() + (stencilKind ? " (index arrays)" : "");
            } else if (field(k, "s") != null && field(k, "e") != null) {
                count = (Integer) field(k, "e") - (Integer) field(k, "s");
            } else if (field(k, "n") != null) {
                count = (Integer) field(k, "n");
                Object pairs = field(k, "pairs");
                if (pairs != null) {
                    name = name + "(" + pairs + " listed pairs)";
                }
            }
        } catch (ReflectiveOperationException | RuntimeException e) {
            count = -1;
        }
        return new String[] {name.replace('~', '-').replace('|', '/'), Long.toString(count)};
    }

    /** @return the neighbour-list rebuild counter of a contact-group kernel, or -1 for other kernels. */
    private static long rebuilds(Object k) {
        try {
            Object v = field(k, "rebuilds");
            return v instanceof Long ? (Long) v : -1;
        } catch (ReflectiveOperationException | RuntimeException e) {
            return -1;
        }
    }

    /** @return the value of a declared field (of the class or a superclass), or null if there is none. */
    private static Object field(Object o, String name) throws ReflectiveOperationException {
        for (Class<?> c = o.getClass(); c != null; c = c.getSuperclass()) {
            try {
                Field f = c.getDeclaredField(name);
                f.setAccessible(true);
                return f.get(o);
            } catch (NoSuchFieldException e) {
                // try the superclass
            }
        }
        return null;
    }
}
