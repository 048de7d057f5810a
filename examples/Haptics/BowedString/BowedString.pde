/*
 * BowedString: a string you bow with the Haply's handle. The handle is the bow: hold it over the bowing point
 * (the marked zone near the left end) to press the bow on the string, and draw it up or down across the string;
 * move it away along the string to lift the bow. The bow's friction on the string is Faust mi.lib's nlBow
 * (Tactus's Bow3D, docs/modules.md): it grips while the bow and the string move together and lets go when they
 * slide apart, the stick-slip that makes a violin string sound. That friction is also what your hand feels. The
 * string sounds at 44.1 kHz through a PhyUGen; a 1 kHz haptic loop gives you the force.
 * With no Haply plugged in, an emulated one is used and the mouse is the hand (the screen says so); until the
 * mouse moves, the emulated hand tours the workspace on its own.
 *
 * Bowing speed: the friction peaks when the bow slides a third of its velocity scale faster than the string
 * (scale 3e-4 model units per audio step, about 0.5 m/s of the hand with alpha = 25): draw the bow at a steady
 * 5-20 cm/s for a clean tone; faster, it slides without gripping. The bow's pressure is its friction Z, set from
 * how close the handle is to the bowing point along the string (a parameter change from draw(), queued to the
 * audio thread between two samples).
 */

import tactus.*;
import tactus.audio.*;
import tactus.haptics.*;
import ddf.minim.*;

// ---- the string (algorithmic units: per audio step)
int masses = 30;          // moving masses of the string
float spacing = 0.1;      // distance between neighbours at rest
float restLength = 0.05;  // length parameter of the links: shorter than the spacing, so the string is taut
float stiffness = 0.2;    // link stiffness
float damping = 0.0001;   // link damping
int bowAt = 4;            // the bowed mass: near the end, as on a violin
float bowZ = 1.5;         // the bow's friction at full pressure (mi.lib's z); its stick slope 2Z/3 stays below 2M
float bowScale = 3e-4;    // the bow's velocity scale (mi.lib's scale), per step
float reach = 0.25;       // the bow presses while the handle is within this distance of the bowing point (along x)
float volume = 40;        // listening gain

// ---- device mapping: model = (-alpha x + ox, alpha y + oy) for the handle at (x, y) metres
float alpha = 25;         // model units per metre
float beta = 8000;        // newtons per model force unit: the peak friction, 2Z/3 * scale/3, is about 0.8 N
float stringLength = (masses + 1) * spacing;
float ox, oy;

// ---- screen
float zoom = 260;
float left, top;

PhysicalModel mdl;
PhyUGen string;
ListeningPoint ear;
AvatarExchange exchange;
Minim minim;
AudioOutput out;
HapticSession haptics;
HapticLoop loop;
ModelRenderer renderer;
double[] force = new double[2];
double[] handle = new double[2];
float pressure = 0;        // the bow's pressure now, 0 (lifted) to 1
boolean pressAgain = true; // set the bow's friction at the next frame

void setup() {
  size(900, 500);
  frameRate(60);
  left = (width - zoom * stringLength) / 2;
  top = 300;

  // The model: a string of Mass2DPlane masses between two fixed points, and the bow (the haptic avatar) tied to
  // the bowed mass by a Bow3D, whose friction acts against the relative velocity of the bow and the string.
  mdl = new PhysicalModel(44100, 60, paramSystem.ALGO_UNITS);
  mdl.setGravity(0);
  mdl.setFriction(0.00001);
  mdl.addGround3D("g0", new Vect3D(0, 0, 0));
  for (int i = 1; i <= masses; i++) {
    mdl.addMass2DPlane("m" + i, 1, new Vect3D(i * spacing, 0, 0), new Vect3D());
  }
  mdl.addGround3D("g" + (masses + 1), new Vect3D(stringLength, 0, 0));
  for (int i = 0; i <= masses; i++) {
    String a = i == 0 ? "g0" : "m" + i;
    String b = i == masses ? "g" + (masses + 1) : "m" + (i + 1);
    mdl.addSpringDamper3D("s" + i, restLength, stiffness, damping, a, b);
  }
  mdl.addHapticInput3D("bow", new Vect3D(bowAt * spacing, -0.4, 0), 40);
  mdl.addBow3D("hair", 0, bowScale, 0, "bow", "m" + bowAt);   // lifted until the handle comes near
  mdl.init();

  // Audio: the PhyUGen steps the model at the output's rate and listens to mass 9 (y displacement).
  string = new PhyUGen(mdl);
  ear = string.listenToMass("m9", SteppedModel.Y, volume, 0);
  exchange = new AvatarExchange(AvatarExchange.ForceMode.SUM);
  string.attachAvatar("bow", exchange);
  minim = new Minim(this);
  out = LineOut.open(minim);      // a silent real-time output when there is no sound card
  pluck(masses / 3, 0.02);        // a first sound at once, so that you hear that the sound works
  string.patch(out);

  // Haptics: the first Haply found, or the emulator with the mouse as the hand.
  haptics = HapticSession.open(this);
  double[] box = new double[4];
  haptics.deviceWorkspace(box);
  // the middle of the workspace lands on the bowing point, so that the bow starts on the string
  ox = (float) (bowAt * spacing + alpha * 0.5 * (box[0] + box[1]));
  oy = (float) (-alpha * 0.5 * (box[2] + box[3]));
  loop = haptics.attach(new ExchangeAvatarLink(exchange));
  loop.setMode(HapticLoop.Mode.AUDIO);
  loop.setPositionGain(alpha);
  loop.setForceGain(beta);
  loop.setOrigin(ox, oy, 0);
  loop.start();
  haptics.setView(zoom, left, top);

  renderer = new ModelRenderer(this);
  renderer.setScale(zoom);
  renderer.setSize(matModuleType.Mass2DPlane, 0.012);
  renderer.setScaling(matModuleType.Mass2DPlane, 0);
  renderer.setColor(matModuleType.Mass2DPlane, 250, 210, 120);
  renderer.setSize(matModuleType.Ground3D, 0.025);
  renderer.setScaling(matModuleType.Ground3D, 0);
  renderer.setSize(matModuleType.HapticInput3D, 0.03);
  renderer.setScaling(matModuleType.HapticInput3D, 0);
  renderer.setColor(matModuleType.HapticInput3D, 230, 60, 60);
  renderer.setColor(linkModuleType.SpringDamper3D, 90, 200, 230, 255);
}

void draw() {
  background(20, 24, 32);
  loop.devicePosition(handle);
  loop.deviceForce(force);
  float mx = (float) (-alpha * handle[0] + ox);
  float my = (float) (alpha * handle[1] + oy);

  // The bow's pressure: full over the bowing point, none beyond 'reach' along the string.
  // (no position yet before the loop's first tick: the bow stays lifted)
  float p = Float.isNaN(mx) ? 0 : constrain(1 - abs(mx - bowAt * spacing) / reach, 0, 1);
  if (pressAgain || abs(p - pressure) > 0.02 || (p == 0) != (pressure == 0)) {
    pressAgain = false;
    pressure = p;
    mdl.setLinkDamping("hair", bowZ * pressure);
  }

  pushMatrix();
  translate(left, top);
  // the bowing zone
  noStroke();
  fill(255, 255, 255, 18);
  rect((bowAt * spacing - reach) * zoom, -150, 2 * reach * zoom, 300);
  // the bow's hair: a line across the handle, bright while it presses
  renderer.renderModel(mdl);
  float hx = mx * zoom, hy = my * zoom;
  stroke(230, 200, 150, 60 + 195 * pressure);
  strokeWeight(2 + 3 * pressure);
  line(hx - 60, hy, hx + 60, hy);
  // the force on the hand (yellow arrow, 60 px per newton)
  stroke(255, 230, 90);
  strokeWeight(3);
  line(hx, hy, hx - (float) force[0] * 60, hy + (float) force[1] * 60);
  popMatrix();

  fill(220);
  textSize(14);
  text("Bow the string: hold the handle in the light zone and draw it steadily up or down, across the string.", 16, 24);
  text("Away from the zone the bow lifts.  Draw at 5-20 cm/s; faster, the bow slides without gripping.", 16, 44);
  text("UP / DOWN: volume (" + nf(volume, 1, 0) + ")   [ and ]: bow friction (" + nf(bowZ, 1, 2)
    + ")   SPACE: pluck it   R: still the string", 16, 64);
  text(String.format("bow pressure %.0f %%   friction on the hand %.2f N   audio %.0f Hz", 100 * pressure,
    Math.hypot(force[0], force[1]), out.sampleRate()), 16, height - 34);
  haptics.drawStatus();
}

// Lifts the string into a triangle of the given height with its apex at mass 'at', and lets it go.
void pluck(int at, float height) {
  for (int i = 1; i <= masses; i++) {
    float y = i <= at ? height * i / at : height * (masses + 1 - i) / (masses + 1 - at);
    mdl.setMatPosition("m" + i, new Vect3D(i * spacing, y, 0));
  }
}

void keyPressed() {
  if (key == '[' || key == ']') {
    bowZ = constrain(bowZ * (key == ']' ? 1.25 : 0.8), 0.1, 2.9);
    pressAgain = true;
  } else if (key == ' ') {
    pluck(int(random(3, masses - 2)), 0.02);
  } else if (key == 'r' || key == 'R') {
    pluck(1, 0);
  } else if (keyCode == UP || keyCode == DOWN) {
    volume = constrain(volume * (keyCode == UP ? 1.25 : 0.8), 1, 300);
    ear.setGain(volume);
  }
}
