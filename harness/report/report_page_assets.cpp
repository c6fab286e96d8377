#include "report/report_page_assets.h"

namespace rayspec {

const char* const kReportStyle = R"(body{font-family:sans-serif;margin:1.5em;color:#222}
table{border-collapse:collapse;margin:.5em 0}td,th{border:1px solid #ccc;padding:2px 6px;font-size:13px}
.Pass{color:#1a7f37}.Fail,.Crash,.Timeout{color:#cf222e;font-weight:bold}.QualityWarning{color:#9a6700}
.CaseError{color:#8250df;font-weight:bold}.undefined{background:#f6f0ff}
.NotSupported{color:#57606a}.case{border:1px solid #ddd;padding:.5em 1em;margin:1em 0}
.images figure{display:inline-block;margin:0 1em 0 0}.images img{image-rendering:pixelated;width:256px;border:1px solid #999}
.uncovered{color:#cf222e}[hidden]{display:none!important}td.n,#others td:nth-child(4){text-align:right}
#filter{position:sticky;top:0;background:#fff;padding:.4em 0;border-bottom:1px solid #ccc;z-index:1}
#filter input[type=search]{width:22em}table.rays:not(.all) tr.same{display:none}
tr.ray th{text-align:left;background:#f3f3f3}summary{cursor:pointer;color:#0550ae}
#by-rule>summary{font-weight:bold;font-size:1.17em;color:inherit;margin:1em 0})";

const char* const kReportCheckScript =
    R"(window.rayspecErrors=0;window.addEventListener('error',function(e){
if(e.target&&e.target.tagName==='IMG')return;window.rayspecErrors++;
document.body.dataset.scriptErrors=window.rayspecErrors;},true);)";

// Each case is one element with data-s (status) and data-f (family); its
// rules are the words of its ".r" element. Matching text is
// read once, lower-cased, on the first filter.
const char* const kReportScript = R"((function(){
var get=function(id){return document.getElementById(id);};
var dec=function(v){try{return decodeURIComponent(v);}catch(e){return v;}};
var cases=Array.prototype.slice.call(document.querySelectorAll('[data-s]'));
var sel={status:get('f-status'),family:get('f-family'),rule:get('f-rule')},q=get('f-search');
function apply(){
var s=sel.status.value,f=sel.family.value,r=sel.rule.value,t=q.value.toLowerCase(),n=0;
cases.forEach(function(c){
if(c.rules===undefined){var e=c.querySelector('.r');c.rules=e?e.textContent.split(' '):[];
c.text=c.textContent.toLowerCase();}
var ok=(!s||c.dataset.s===s)&&(!f||c.dataset.f===f)&&(!r||c.rules.indexOf(r)>=0)&&
(!t||c.text.indexOf(t)>=0);c.hidden=!ok;if(ok)n++;});
Array.prototype.forEach.call(document.querySelectorAll('.group'),function(g){
g.querySelector('.shown').textContent=g.querySelectorAll('[data-s]:not([hidden])').length;});
get('shown').textContent=n+' of '+cases.length+' cases shown';document.body.dataset.shown=n;}
function toHash(){var p=[];for(var k in sel)if(sel[k].value)p.push(k+'='+encodeURIComponent(sel[k].value));
if(q.value)p.push('q='+encodeURIComponent(q.value));
try{history.replaceState(null,'',p.length?'#filter?'+p.join('&'):location.pathname);}catch(e){}}
function fromHash(){var h=location.hash.slice(1);
if(h.indexOf('filter?')!==0){var e=h&&get(dec(h));
if(e&&e.hidden){for(var k in sel)sel[k].value='';q.value='';apply();e.scrollIntoView();}return;}
var p={};h.slice(7).split('&').forEach(function(kv){var i=kv.indexOf('=');
if(i>0)p[kv.slice(0,i)]=dec(kv.slice(i+1));});
for(var k in sel){sel[k].value=p[k]||'';if(sel[k].selectedIndex<0)sel[k].value='';}
q.value=p.q||'';apply();}
for(var k in sel)sel[k].addEventListener('change',function(){apply();toHash();});
q.addEventListener('input',function(){apply();toHash();});
get('f-clear').addEventListener('click',function(){for(var k in sel)sel[k].value='';q.value='';
apply();toHash();});
document.addEventListener('change',function(e){var t=e.target;if(!t.classList.contains('allf'))return;
t.closest('details').querySelector('table.rays').classList.toggle('all',t.checked);});
window.addEventListener('hashchange',fromHash);apply();fromHash();
window.addEventListener('load',function(){var ok=0,broken=[];
Array.prototype.forEach.call(document.images,function(i){
if(i.complete&&i.naturalWidth>0)ok++;else broken.push(i.getAttribute('src'));});
var b=document.body.dataset;b.images=ok;b.brokenImages=broken.length;b.brokenList=broken.join(' ');
b.scriptErrors=window.rayspecErrors;b.checked='1';});})();)";

}  // namespace rayspec
