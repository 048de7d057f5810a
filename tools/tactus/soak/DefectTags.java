package tactus.soak;

/**
 * Names the defect of issue 15 ("Real-time threads that survive every mistake", section 1) that a failure most
 * likely is, from its family, its message and the frames of its stack. The match is a heuristic on class and
 * method names of today's code; a failure that matches nothing is tagged "new" and deserves a look. What the soak
 * found on the code before the fixes (defects 2, 3, 4, 5, 7 and the section 2 races), with the runs that showed
 * each, is listed in docs/audio.md ("Soak").
 *
 * <ul>
 *   <li>1: a queued change whose target is gone throws inside {@code Ownership.drain()} (escape on the stepping
 *       thread) and leaves the gate held, so callers waiting in {@code Ownership.awaitApplied} hang.</li>
 *   <li>2: a ramp writes to a removed subset member: "no live link with id" / {@code RampTargets}.</li>
 *   <li>3: any exception out of {@code PhyUGen.uGenerate} on Minim's output thread (divergence with no listener,
 *       removed listened mass or avatar, {@code clearModel()}, a listener that throws); the output stops.</li>
 *   <li>4: calls made while holding {@code getLock()}: on a thread the model takes for its owner, the first call
 *       releases the caller's own hold ({@code IllegalMonitorStateException} at its {@code unlock()}), and the
 *       caller goes on without the lock.</li>
 *   <li>5: readers mutate engine state: {@code ContactGroupKernel} out of bounds on either thread, or a reader
 *       ({@code StateAccess}, e.g. {@code getTotalEnergy}) compiling the plan ({@code PlanCompiler}) while another
 *       thread compiles or steps.</li>
 *   <li>An out-of-bounds in {@code PlanCompiler} on an editing thread: two threads rebuilt or read the plan at once
 *       (section 2 of the issue: more than one thread acts as the stepper).</li>
 *   <li>6: {@code StabilityMessages} writes the live engine from a helper thread.</li>
 *   <li>7: {@code endRealtimeStepping()} from a divergence listener deadlocks the audio thread.</li>
 *   <li>8: a structural undo compiled on the audio thread ({@code PlanCompiler} under {@code uGenerate}).</li>
 *   <li>10: {@code PhysicalModelStepper}'s shared scratch vector.</li>
 * </ul>
 */
final class DefectTags {
    private DefectTags() {
    }

    /**
     * @param what where the failure was (thread, call) and its message
     * @return e.g. "defect 1 (queued command whose target is gone)", or "new" when nothing matches
     */
    static String tag(String family, String what, String stack) {
        String all = what + "\n" + stack;
        if (all.contains("endRealtimeStepping") && all.contains("diverged")) {
            return "defect 7 (endRealtimeStepping from a divergence listener)";
        }
        if (all.contains("Ownership.drain") || all.contains("Ownership.awaitApplied")
                || all.contains("Ownership.awaitAll")) {
            return "defect 1 (queued change whose target is gone / gate left held)";
        }
        if (all.contains("RampTargets") || all.contains("no live link with id") || all.contains("no live mass with id")) {
            return "defect 2 (ramp writes a removed subset member)";
        }
        if (all.contains("IllegalMonitorStateException") && all.contains("getLock")) {
            return "defect 4 (a call made while holding getLock() released the caller's hold)";
        }
        if (all.contains("StateAccess") && all.contains("PlanCompiler")) {
            return "defect 5 (a reader compiles the plan: reader mutates engine state)";
        }
        if (all.contains("ContactGroupKernel")) {
            return "defect 5 (reader rebuilds the contact broad phase)";
        }
        if (all.contains("StabilityMessages")) {
            return "defect 6 (stability helper writes the live engine)";
        }
        if (all.contains("PlanCompiler") && all.contains("uGenerate")) {
            return "defect 8 (compile on the audio thread)";
        }
        if (all.contains("PhysicalModelStepper") && all.contains("scratch")) {
            return "defect 10 (shared scratch vector)";
        }
        if (family.equals("HANG") && all.contains("stepping stalled")) {
            return "defect 1 (gate left STEPPING: the model runs 0 steps)";
        }
        if (all.contains("PhyUGen.uGenerate") || all.contains("audio output stopped")) {
            return "defect 3 (exception out of PhyUGen.uGenerate kills Minim's output)";
        }
        if (all.contains("PlanCompiler")) {
            return "issue section 2 / defects 1, 4, 5 (two threads compile or step at once: an editor draining the queue "
                    + "while the owner looks idle, a reader compiling, a lost getLock() hold)";
        }
        return "new";
    }
}
