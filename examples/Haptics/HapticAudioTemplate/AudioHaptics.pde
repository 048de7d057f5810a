// The audio-haptic machinery of the template: nothing to change here to try a new model.
// Audio: a PhyUGen steps the model once per sample (44.1 kHz) inside Minim's output (LineOut gives a silent
// real-time output when there is no sound card). Haptics: a HapticSession opens the first Haply found (or the
// emulator, whose hand tours the workspace on its own until the mouse moves, then follows the mouse) and runs
// its 1 kHz loop in AUDIO mode: it hands the device position to the audio thread and takes the force on the
// avatar back through an AvatarExchange, without locks. The exchange pairs the summed force with the number of
// audio steps it covers, so the loop renders the exact mean force per audio step (held between Minim's bursts).
// (Attaching the session straight to the model's avatar, haptics.attach(mdl, "avatar"), also runs, but while the
// audio thread steps the model that path reads the force and the step count in two calls, so now and then a tick
// renders a wrong force for a millisecond; see PluckedString.) Drawing: ModelRenderer, from a snapshot.

PhysicalModel mdl;
PhyUGen ugen;
AvatarExchange exchange;
Minim minim;
AudioOutput out;
HapticSession haptics;
HapticLoop loop;
ModelRenderer renderer;
double[] handForce = new double[2];
double[] handPosition = new double[2];
float alpha, ox, oy;

void setup() {
  size(900, 500);
  frameRate(60);

  mdl = new PhysicalModel(44100, 60, paramSystem.ALGO_UNITS);
  mdl.setGravity(0);
  mdl.setFriction(0.00001);
  buildModel(mdl);
  mdl.init();

  ugen = new PhyUGen(mdl);
  listen(ugen);
  exchange = new AvatarExchange(AvatarExchange.ForceMode.SUM);   // the loop takes the mean per step itself
  ugen.attachAvatar("avatar", exchange);
  minim = new Minim(this);
  out = LineOut.open(minim);
  ugen.patch(out);

  // model = (-alpha x + ox, alpha y + oy) for the handle at (x, y) metres; the middle of the device's
  // workspace is the model's origin. The session closes the board when the sketch ends.
  haptics = HapticSession.open(this);               // other hardware: HapticSession.open(this, HaplyPreset.TWO_DIY_V3)
  double[] box = new double[4];
  haptics.deviceWorkspace(box);                     // metres
  alpha = ZOOM_MODEL * 100;
  ox = (float) (alpha * 0.5 * (box[0] + box[1]));
  oy = (float) (-alpha * 0.5 * (box[2] + box[3]));
  loop = haptics.attach(new ExchangeAvatarLink(exchange));  // position to the audio thread, force back
  loop.setMode(HapticLoop.Mode.AUDIO);
  loop.setPositionGain(alpha);
  loop.setForceGain(FORCE_GAIN);
  loop.setOrigin(ox, oy, 0);
  loop.start();
  haptics.setView(PIXELS_PER_UNIT, width / 2, height / 2);   // how the model is drawn: the mouse lands on the avatar

  renderer = new ModelRenderer(this);
  renderer.setScale(PIXELS_PER_UNIT);
  for (matModuleType t : matModuleType.values()) {
    renderer.setSize(t, 0.012);
    renderer.setScaling(t, 0);
  }
  renderer.setSize(matModuleType.HapticInput3D, 0.08);
  renderer.setColor(matModuleType.Mass2DPlane, 250, 210, 120);
}

void draw() {
  background(20, 24, 32);
  pushMatrix();
  translate(width / 2, height / 2);
  renderer.renderModel(mdl);
  loop.devicePosition(handPosition);
  loop.deviceForce(handForce);
  float hx = (float) (-alpha * handPosition[0] + ox) * PIXELS_PER_UNIT;
  float hy = (float) (alpha * handPosition[1] + oy) * PIXELS_PER_UNIT;
  noFill();
  stroke(255);
  strokeWeight(1.5);
  ellipse(hx, hy, 10, 10);
  stroke(255, 230, 90);
  strokeWeight(3);
  line(hx, hy, hx - (float) handForce[0] * 60, hy + (float) handForce[1] * 60);
  popMatrix();

  fill(220);
  textSize(14);
  text("Move the avatar (red) with the Haply, or with the mouse when there is none. Yellow: the force you feel.", 16, 24);
  text("Write your own model in buildModel() in the first tab.", 16, 44);
  text(String.format("force on the handle %.2f N", Math.hypot(handForce[0], handForce[1])), 16, height - 34);
  haptics.drawStatus();   // which board, or that the mouse is the hand (and why the loop stopped, if it did)
}
