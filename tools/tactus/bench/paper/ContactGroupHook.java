package tactus.bench.paper;

import java.util.function.Consumer;
import tactus.PhysicalModel;

/**
 * Tactus only: gives the marbles of {@link PaperScenes#marbles} one contact group over the subset "marbles" (threshold
 * 0.2, K 0.02, Z 0.01, the values of the explicit Contact3D links) in place of one Contact3D per pair. The paper's
 * engine has no contact group; {@link PaperScenes} loads this class by name so that its source still compiles
 * against that engine.
 */
public final class ContactGroupHook implements Consumer<Object> {
    /** Creates the hook. */
    public ContactGroupHook() {
    }

    /** @param model the {@link PhysicalModel} being built, with its subset "marbles" */
    @Override
    public void accept(Object model) {
        ((PhysicalModel) model).addContactGroup("marbles", 0.2, 0.02, 0.01);
    }
}
