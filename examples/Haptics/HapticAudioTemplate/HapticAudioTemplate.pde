/*
 * HapticAudioTemplate: a starting point for your own audio-haptic model. Write the model in buildModel()
 * below and say what to listen to in listen(); the other tab (AudioHaptics) plays it at 44.1 kHz through
 * Minim, runs the 1 kHz haptic loop of a Haply on the avatar, and draws everything, so this tab holds model
 * code only. With no Haply plugged in, an emulated one is used and the mouse is the hand (the screen says so);
 * until the mouse moves, the emulated hand tours the middle of the workspace on its own.
 */

import tactus.*;
import tactus.audio.*;
import tactus.haptics.*;
import ddf.minim.*;

// Units are algorithmic (per audio step). The model's origin is the middle of the Haply's workspace and
// 1 cm of handle motion is ZOOM_MODEL units; 1 model unit is drawn as PIXELS_PER_UNIT pixels.
float ZOOM_MODEL = 0.25;       // model units per centimetre of handle motion
float FORCE_GAIN = 1500;       // newtons on the handle per model force unit (force averaged per audio step)
float PIXELS_PER_UNIT = 260;

/**
 * Builds the model. It must contain a HapticInput3D named "avatar": the haptic device drives it and feels
 * the forces on it. Replace this example (a short taut string that the avatar can pluck) with yours.
 */
void buildModel(PhysicalModel mdl) {
  int n = 20;
  float spacing = 0.1;
  float x0 = -spacing * (n + 1) / 2;
  mdl.addGround3D("end0", new Vect3D(x0, 0, 0));
  for (int i = 1; i <= n; i++) {
    mdl.addMass2DPlane("m" + i, 1, new Vect3D(x0 + i * spacing, 0, 0), new Vect3D());
  }
  mdl.addGround3D("end1", new Vect3D(x0 + (n + 1) * spacing, 0, 0));
  for (int i = 0; i <= n; i++) {
    String a = i == 0 ? "end0" : "m" + i;
    String b = i == n ? "end1" : "m" + (i + 1);
    mdl.addSpringDamper3D("link" + i, 0.05, 0.3, 0.0001, a, b);
  }
  mdl.addHapticInput3D("avatar", new Vect3D(0, -0.5, 0), 40);
  for (int i = 1; i <= n; i++) {
    mdl.addContact3D("touch" + i, 0.08, 0.01, 0.001, "avatar", "m" + i);
  }
}

/** Says what the PhyUGen plays: listening points with a gain and a stereo pan (-1 left .. 1 right). */
void listen(PhyUGen ugen) {
  ugen.listenToMass("m3", SteppedModel.Y, 30, -0.3);
  ugen.listenToMass("m17", SteppedModel.Y, 30, 0.3);
}
