#!/usr/bin/env bash
# fxkit-view driven by --script: a scripted parameter change changes the picture (and a
# frame with no change does not), at the default size the scene is right of the panel, a
# saved edit arrives through wait-reload (a failed one makes the exit status 1), a texture
# file replaces the stand-in, and commands that cannot run fail at their line.
# Usage: viewer_script.sh XVFB_RUN FXKIT_VIEW EFFECT WORK_DIR
set -euo pipefail
# Under the sanitizer build: GLFW's X11 and Vulkan libraries, loaded with dlopen and closed at
# exit, leave allocations LeakSanitizer cannot attribute (frames in an unknown module, so no
# suppression can name them) and it aborts the viewer; leak checking stays on for the rest.
export ASAN_OPTIONS="${ASAN_OPTIONS:+$ASAN_OPTIONS:}detect_leaks=0"
xvfb=$1 view=$2 effect=$3 work=$4
rm -rf "$work" && mkdir -p "$work"
cp "$effect" "$work/lit.fx"
cd "$work"

cat >set.script <<'END'
frames 2
screenshot before.png
set Tint 1,0.1,0.1,1   # red
frames 2
screenshot after.png
screenshot again.png   # nothing changed since
quit
END
"$xvfb" -a "$view" lit.fx --size 160x120 --validate --script set.script >set.log 2>&1 || { cat set.log; exit 1; }
cat set.log
cmp -s before.png after.png && { echo "set Tint did not change the picture"; exit 1; }
cmp -s after.png again.png || { echo "two frames with no change differ"; exit 1; }

# At the default size the scene is drawn right of the panel (360 pixels wide), so the panel
# covers none of the mesh; a window narrower than that leaves the panel over the scene.
printf 'frames 2\nscreenshot wide.png\n' >wide.script
"$xvfb" -a -s "-screen 0 1280x800x24" "$view" lit.fx --validate --script wide.script >wide.log 2>&1 || { cat wide.log; exit 1; }
cat wide.log
left=$(sed -n 's/.*pixels drawn in columns \([0-9]*\) to .*/\1/p' wide.log)
[ -n "$left" ] && [ "$left" -ge 360 ] || { echo "the mesh starts at column '$left', under the panel"; exit 1; }

# Waits are for what the viewer writes; a wait gives up after 60 s times FXKIT_TEST_SLOWDOWN
# (10 in sanitizer builds).
patience=$((60 * ${FXKIT_TEST_SLOWDOWN:-1}))
cat >reload.script <<END
frames 2
screenshot loaded.png
wait-reload $patience
frames 2
screenshot edited.png
END
"$xvfb" -a "$view" lit.fx --size 160x120 --validate --script reload.script >reload.log 2>&1 &
pid=$!
give_up=$((SECONDS + patience))
while ((SECONDS < give_up)) && ! [ -s loaded.png ]; do sleep 0.1; done
[ -s loaded.png ] || { echo "no first screenshot"; cat reload.log; kill $pid; exit 1; }
sed -i 's/float4 Tint = {[^}]*}/float4 Tint = {0.1, 0.9, 0.1, 1.0}/' lit.fx
wait $pid || { echo "the reload script failed"; cat reload.log; exit 1; }
cat reload.log
grep -q "^reloaded " reload.log || { echo "no reload reported"; exit 1; }
cmp -s loaded.png edited.png && { echo "the saved edit did not change the picture"; exit 1; }

# A wait-reload that sees a failed reload goes on with the script, and the run's exit status
# is 1: what was on screen was the last good version, not the file as saved.
cp lit.fx broken.fx
cat >broken.script <<END
frames 2
screenshot broken_loaded.png
wait-reload $patience
frames 2
END
"$xvfb" -a "$view" broken.fx --size 160x120 --script broken.script >broken.log 2>&1 &
pid=$!
give_up=$((SECONDS + patience))
while ((SECONDS < give_up)) && ! [ -s broken_loaded.png ]; do sleep 0.1; done
[ -s broken_loaded.png ] || { echo "no first screenshot"; cat broken.log; kill $pid; exit 1; }
echo "technique broken { pass p0 { VertexShader = compile vs_2_0 Nowhere(); } }" >>broken.fx
if wait $pid; then echo "a run whose last reload failed exited 0"; cat broken.log; exit 1; fi
grep -q "^failed " broken.log || { echo "no failed reload reported"; cat broken.log; exit 1; }

# A texture parameter sampled from a file the script names (Effect::set_texture_file).
cat >textured.fx <<'END'
float4x4 WorldViewProjection : WORLDVIEWPROJECTION;
texture Picture < string ResourceName = "not_there.png"; >;
sampler2D PictureSampler = sampler_state { Texture = <Picture>; };
struct V { float4 position : POSITION; float2 uv : TEXCOORD0; };
V VS(float4 p : POSITION, float2 uv : TEXCOORD0) { V o; o.position = mul(p, WorldViewProjection); o.uv = uv; return o; }
float4 PS(V i) : COLOR0 { return tex2D(PictureSampler, i.uv); }
technique T { pass P { VertexShader = compile vs_2_0 VS(); PixelShader = compile ps_2_0 PS(); } }
END
cat >texture.script <<'END'
frames 2
screenshot stand_in.png
texture Picture before.png
frames 2
screenshot textured.png
END
"$xvfb" -a "$view" textured.fx --size 160x120 --validate --script texture.script >texture.log 2>&1 || { cat texture.log; exit 1; }
cat texture.log
cmp -s stand_in.png textured.png && { echo "texture Picture before.png did not change the picture"; exit 1; }

printf 'frames 1\ntexture Picture no_such_file.png\n' >bad_texture.script
if "$xvfb" -a "$view" textured.fx --size 160x120 --script bad_texture.script >bad_texture.log 2>&1; then
  echo "a script sampling a missing file succeeded"; cat bad_texture.log; exit 1
fi
grep -q "bad_texture.script:2: error: cannot sample 'no_such_file.png'" bad_texture.log || { cat bad_texture.log; exit 1; }

printf 'frames 1\nset NoSuchParam 1\n' >bad.script
if "$xvfb" -a "$view" lit.fx --size 160x120 --script bad.script >bad.log 2>&1; then
  echo "a script setting a missing parameter succeeded"; cat bad.log; exit 1
fi
grep -q "bad.script:2: error: cannot set 'NoSuchParam'" bad.log || { cat bad.log; exit 1; }
echo "viewer script: ok"
